// The deploy node's scan handling without a master: a LaserScan resampled to the policy's beams
// (wrapping, refusal of uncovered beams) and read as the navigation task's observer reads a
// simulated scan (REP 117's infinities, NaN, clamping), and the beams taken from the checkpoint,
// parameters that disagree with it refused naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/ros/deploy/scan_beams.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace {

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

/// Beams at `angles` read from the nearest sample (a checkpoint without sectors).
ObserverSpec nearest(const std::vector<double>& angles) {
  ObserverSpec beams;
  beams.scan_beam_angles = angles;
  return beams;
}

/// The scan's readings at `angles` as the navigation observer of a scanner of [range_min,
/// range_max] holds them.
std::vector<float> observedBeams(const sensor_msgs::LaserScan& s, const std::vector<double>& angles,
                                 double range_min, double range_max, std::string& error) {
  std::vector<float> ranges;
  if (!resampleScan(s, nearest(angles), ranges, error)) return {};
  const NavigationObserver observer(static_cast<int>(angles.size()), range_min, range_max, 2, 0.2);
  std::vector<float> beams;
  for (float r : ranges) beams.push_back(observer.beamValue(r));
  return beams;
}

TEST(ResampleScan, NearestSampleOfAFullTurnWrapsAndInfinitiesReadTheRangeEnds) {
  sensor_msgs::LaserScan s = scan(8, 0.0, kPi / 4);  // 0 .. 7 pi / 4: a full turn
  s.ranges[4] = kInf;                                // beyond range_max (REP 117)
  s.ranges[2] = -kInf;                               // below range_min
  s.ranges[6] = std::numeric_limits<float>::quiet_NaN();
  std::string error;
  // -pi/4 wraps to sample 7; 0.1 rad is nearest sample 0; pi/2 is 2; pi is 4; -pi/2 wraps to 6.
  std::vector<float> ranges;
  ASSERT_TRUE(resampleScan(s, nearest({-kPi / 4, 0.1, kPi / 2, kPi, -kPi / 2}), ranges, error))
      << error;
  ASSERT_EQ(ranges.size(), 5u);
  EXPECT_EQ(ranges[0], 1.7f);
  EXPECT_EQ(ranges[1], 1.0f);
  EXPECT_EQ(ranges[2], -kInf);  // as the scan holds them: the observer reads them
  EXPECT_EQ(ranges[3], kInf);
  EXPECT_TRUE(std::isnan(ranges[4]));
  const std::vector<float> b =
      observedBeams(s, {-kPi / 4, 0.1, kPi / 2, kPi, -kPi / 2}, 0.15, 2.0, error);
  ASSERT_EQ(b.size(), 5u);
  EXPECT_FLOAT_EQ(b[0], 1.7f / 2.0f);
  EXPECT_FLOAT_EQ(b[1], 1.0f / 2.0f);
  EXPECT_FLOAT_EQ(b[2], 0.15f / 2.0f);  // -inf: range_min
  EXPECT_FLOAT_EQ(b[3], 1.0f);          // +inf: range_max
  EXPECT_FLOAT_EQ(b[4], 1.0f);          // NaN: range_max
  // Readings beyond the policy's range are clamped into it.
  EXPECT_FLOAT_EQ(observedBeams(s, {5 * kPi / 4}, 0.15, 1.2, error)[0], 1.0f);
}

TEST(ResampleScan, ABeamOutsideAPartialScanIsRefusedNamingTheAngles) {
  const sensor_msgs::LaserScan s = scan(5, -1.0, 0.5);  // [-1, 1] rad
  std::string error;
  std::vector<float> ranges;
  EXPECT_FALSE(resampleScan(s, nearest({0.0, 2.0}), ranges, error));
  EXPECT_NE(error.find("the policy needs a beam at 2.0"), std::string::npos) << error;
  EXPECT_NE(error.find("the scan covers [-1.0"), std::string::npos) << error;
}

TEST(ResampleScan, SectorsTakeTheSmallestReadingAndAClockwiseScanReadsTheSame) {
  sensor_msgs::LaserScan s = scan(8, 0.0, kPi / 4);  // readings 1.0, 1.1, ..., 1.7
  s.ranges[3] = 0.5f;
  ObserverSpec beams = nearest({0.0, kPi / 2, kPi, 3 * kPi / 2});
  beams.scan_beam_width = kPi / 2;  // two samples a beam
  std::vector<float> ranges;
  std::string error;
  ASSERT_TRUE(resampleScan(s, beams, ranges, error)) << error;
  EXPECT_EQ(ranges, (std::vector<float>{s.ranges[0], 0.5f, s.ranges[4], s.ranges[6]}));
  // The same scan from a driver that lists it clockwise (negative increment).
  sensor_msgs::LaserScan clockwise = s;
  std::reverse(clockwise.ranges.begin(), clockwise.ranges.end());
  clockwise.angle_min = static_cast<float>(7 * kPi / 4);
  clockwise.angle_increment = static_cast<float>(-kPi / 4);
  std::vector<float> from_clockwise;
  ASSERT_TRUE(resampleScan(clockwise, beams, from_clockwise, error)) << error;
  EXPECT_EQ(from_clockwise, ranges);
}

}  // namespace
}  // namespace jetbot_rl
