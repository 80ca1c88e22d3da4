// The robot mode's scan handling without a master: a LaserScan resampled to the policy's beams
// (wrapping, REP 117's infinities, NaN, refusal of uncovered beams), and the beams taken from
// the checkpoint, parameters that disagree with it refused naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/ros/navigation_driver.h"

namespace jetbot_rl {
namespace ppo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kInf = std::numeric_limits<float>::infinity();

/// A scan of `n` samples from `angle_min`, `increment` apart, reading 1 + sample index / 10 [m].
sensor_msgs::LaserScan scan(int n, double angle_min, double increment) {
  sensor_msgs::LaserScan s;
  s.angle_min = static_cast<float>(angle_min);
  s.angle_increment = static_cast<float>(increment);
  s.angle_max = static_cast<float>(angle_min + increment * (n - 1));
  for (int i = 0; i < n; ++i) s.ranges.push_back(1.0f + i / 10.0f);
  return s;
}

TEST(ResampleScan, NearestSampleOfAFullTurnWrapsAndInfinitiesReadTheRangeEnds) {
  sensor_msgs::LaserScan s = scan(8, 0.0, kPi / 4);  // 0 .. 7 pi / 4: a full turn
  s.ranges[4] = kInf;                                // beyond range_max (REP 117)
  s.ranges[2] = -kInf;                               // below range_min
  s.ranges[6] = std::numeric_limits<float>::quiet_NaN();
  std::string error;
  // -pi/4 wraps to sample 7; 0.1 rad is nearest sample 0; pi/2 is 2; pi is 4; -pi/2 wraps to 6.
  const std::vector<float> b =
      resampleScan(s, {-kPi / 4, 0.1, kPi / 2, kPi, -kPi / 2}, 0.15, 2.0, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(b.size(), 5u);
  EXPECT_FLOAT_EQ(b[0], 1.7f / 2.0f);
  EXPECT_FLOAT_EQ(b[1], 1.0f / 2.0f);
  EXPECT_FLOAT_EQ(b[2], 0.15f / 2.0f);  // -inf: range_min
  EXPECT_FLOAT_EQ(b[3], 1.0f);          // +inf: range_max
  EXPECT_FLOAT_EQ(b[4], 1.0f);          // NaN: range_max
  // Readings beyond the policy's range are clamped into it.
  EXPECT_FLOAT_EQ(resampleScan(s, {5 * kPi / 4}, 0.15, 1.2, error)[0], 1.0f);
}

TEST(ResampleScan, ABeamOutsideAPartialScanIsRefusedNamingTheAngles) {
  const sensor_msgs::LaserScan s = scan(5, -1.0, 0.5);  // [-1, 1] rad
  std::string error;
  EXPECT_TRUE(resampleScan(s, {0.0, 2.0}, 0.1, 4.0, error).empty());
  EXPECT_NE(error.find("the policy needs a beam at 2.0"), std::string::npos) << error;
  EXPECT_NE(error.find("the scan covers [-1.0"), std::string::npos) << error;
}

/// The spec of an env whose navigation task observed 3 beams.
BatchSpec trainedWithBeams() {
  BatchSpec spec;
  spec.task = "navigation";
  spec.scan_beam_angles = {-1.0, 0.0, 1.0};
  spec.scan_range = {0.15, 3.5};
  return spec;
}

TEST(ScanBeamsOf, TheCheckpointsBeamsAndParametersThatAgreeWithThem) {
  RobotModeParams p;
  ScanBeams beams = scanBeamsOf(trainedWithBeams(), p, "nav.pt");
  EXPECT_EQ(beams.angles, (std::vector<double>{-1.0, 0.0, 1.0}));
  EXPECT_EQ(beams.range_min, 0.15);
  EXPECT_EQ(beams.range_max, 3.5);
  p.scan_angles = {-1.0, 1.0};
  p.scan_range = {0.15, 3.5};
  EXPECT_EQ(scanBeamsOf(trainedWithBeams(), p, "nav.pt").angles, beams.angles);
}

TEST(ScanBeamsOf, ParametersThatDisagreeWithTheCheckpointAreRefusedNamingThem) {
  RobotModeParams p;
  p.scan_range = {0.12, 12.0};
  try {
    scanBeamsOf(trainedWithBeams(), p, "nav.pt");
    FAIL() << "accepted another range than the checkpoint's";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "scan_range = [0.12, 12]: the policy of nav.pt was trained with [0.15, 3.5] m"),
              std::string::npos)
        << e.what();
  }
  p.scan_range.clear();
  p.scan_angles = {-kPi, kPi};
  try {
    scanBeamsOf(trainedWithBeams(), p, "nav.pt");
    FAIL() << "accepted other angles than the checkpoint's";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("scan_angles = [-3.14159, 3.14159]"), std::string::npos)
        << e.what();
  }
}

TEST(ScanBeamsOf, ACheckpointWithoutItsBeamsNeedsTheParameters) {
  BatchSpec old_spec = trainedWithBeams();
  old_spec.scan_beam_angles.clear();
  old_spec.scan_range.clear();
  RobotModeParams p;
  try {
    scanBeamsOf(old_spec, p, "old.pt");
    FAIL() << "accepted a checkpoint without beams and no parameters";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("scan_angles = []: checkpoint old.pt does not hold"),
              std::string::npos)
        << e.what();
  }
  // Given: nav/beams evenly spread over [first, last].
  p.task.navigation.beams = 5;
  p.scan_angles = {-2.0, 2.0};
  p.scan_range = {0.2, 6.0};
  const ScanBeams beams = scanBeamsOf(old_spec, p, "old.pt");
  EXPECT_EQ(beams.angles, (std::vector<double>{-2.0, -1.0, 0.0, 1.0, 2.0}));
  EXPECT_EQ(beams.range_min, 0.2);
  EXPECT_EQ(beams.range_max, 6.0);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
