// readBeams: each beam is the smallest reading of its sector (REP 117's -inf the smallest, NaN
// skipped), a full turn wraps, the nearest sample without a sector, beams the scan does not cover
// refused; and the navigation task sees a 2 cm post that stands between two of its 24 beams.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/sensors/scan_reading.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

TEST(ReadBeams, EachBeamIsTheSmallestReadingOfItsSector) {
  const std::vector<float> r{2.0f, 1.5f, kNoReturn, kNan, kTooClose, 3.0f, kNan, kNan};
  const ScanView scan{r.data(), 8, 0.0, kPi / 4};  // a full turn
  std::vector<float> beams(4);
  std::string error;
  ASSERT_TRUE(readBeams(scan, {0.0, kPi / 2, kPi, 3 * kPi / 2}, kPi / 2, beams.data(), error));
  EXPECT_EQ(beams[0], 1.5f);          // min(2, 1.5)
  EXPECT_EQ(beams[1], kNoReturn);     // +inf, NaN skipped
  EXPECT_EQ(beams[2], kTooClose);     // -inf is the smallest
  EXPECT_TRUE(std::isnan(beams[3]));  // nothing but NaN: the sample nearest the middle
  // The last sector wraps past the end of a full turn.
  ASSERT_TRUE(readBeams(scan, {7 * kPi / 4}, kPi / 2, beams.data(), error));
  EXPECT_EQ(beams[0], 2.0f);  // samples 7 (NaN) and 0
  // Without a sector: the nearest sample, wrapping too.
  ASSERT_TRUE(readBeams(scan, {-0.1, kPi / 4 + 0.2}, 0.0, beams.data(), error));
  EXPECT_EQ(beams[0], 2.0f);
  EXPECT_EQ(beams[1], 1.5f);
}

TEST(ReadBeams, ABeamOutsideAFanIsRefusedNamingTheAngles) {
  const std::vector<float> r(5, 1.0f);
  const ScanView fan{r.data(), 5, -1.0, 0.5};  // [-1, 1] rad
  std::vector<float> beams(2);
  std::string error;
  EXPECT_FALSE(readBeams(fan, {0.0, 2.0}, 0.0, beams.data(), error));
  EXPECT_NE(error.find("needs a beam at 2.0"), std::string::npos) << error;
  // A sector partly outside reads the samples inside.
  EXPECT_TRUE(readBeams(fan, {0.75}, 1.0, beams.data(), error)) << error;
  EXPECT_FALSE(readBeams(ScanView{r.data(), 5, 0.0, 0.0}, {0.0}, 0.0, beams.data(), error));
}

TEST(ReadBeams, APostBetweenTwoOfTwentyFourBeamsIsSeen) {
  // 360 samples read into 24 beams, 15 degrees apart; a 2 cm post 1 m away, 7 degrees past
  // beam 0: no beam's own sample meets it, its sector's samples do.
  const ScannerSpec spec = test::fullTurnScanner(0.12, 3.5);
  Obstacle post;
  post.shape = Obstacle::Shape::kCylinder;
  const double angle = -kPi + 7.0 * kPi / 180.0;
  post.center = Eigen::Vector2d(std::cos(angle), std::sin(angle));
  post.radius = 0.01;
  post.height = 0.3;
  Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
  sensor.translation().z() = 0.1;
  std::vector<float> ranges(360);
  Rng noise(1);
  castScan(spec, nullptr, {post}, sensor, noise, ranges.data());
  std::vector<double> angles;
  for (int i = 0; i < 24; ++i) angles.push_back(spec.min_angle + 15 * i * spec.angleIncrement());
  const ScanView scan{ranges.data(), 360, spec.min_angle, spec.angleIncrement()};
  std::vector<float> sectors(24), nearest(24);
  std::string error;
  ASSERT_TRUE(readBeams(scan, angles, 15 * spec.angleIncrement(), sectors.data(), error));
  ASSERT_TRUE(readBeams(scan, angles, 0.0, nearest.data(), error));
  EXPECT_NEAR(sectors[0], 0.99, 0.01);  // the post
  EXPECT_EQ(nearest[0], kNoReturn);     // one sample a beam misses it
  for (int i = 1; i < 24; ++i) EXPECT_EQ(sectors[i], kNoReturn) << "beam " << i;
}

}  // namespace
}  // namespace jetbot_rl
