// Giving up a goal as move_base does: the time-out, and no progress within the oscillation
// time-out (pushing into a wall, turning on the spot), with progress restarting after a recovery.
#include <gtest/gtest.h>

#include "jetbot_rl/planning/goal_watch.h"

namespace jetbot_rl {
namespace {

GoalWatchConfig watchConfig() {
  GoalWatchConfig c;
  c.timeout = 60.0;
  c.oscillation_timeout = 5.0;
  c.oscillation_distance = 0.2;
  return c;
}

TEST(GoalWatch, ARobotThatKeepsMovingIsPursuingUntilTheTimeOut) {
  GoalWatch watch(watchConfig());
  watch.start(100.0, {0.0, 0.0});
  std::string why;
  for (int k = 1; k <= 590; ++k) {  // 0.1 m/s for 59 s
    const double t = 100.0 + 0.1 * k;
    ASSERT_EQ(watch.check(t, {0.01 * k, 0.0}, why), GoalWatch::Verdict::kPursuing) << t;
  }
  EXPECT_EQ(watch.check(160.5, {6.0, 0.0}, why), GoalWatch::Verdict::kTimedOut);
  EXPECT_NE(why.find("timed out: not reached within 60 s"), std::string::npos) << why;
}

TEST(GoalWatch, ARobotThatMovesLessThanTheDistanceIsStuckAfterTheOscillationTimeOut) {
  GoalWatch watch(watchConfig());
  watch.start(0.0, {1.0, 1.0});
  std::string why;
  // Back and forth 0.15 m (turning on the spot, pushing into a wall): no progress.
  for (int k = 1; k <= 50; ++k) {
    const double x = 1.0 + ((k % 2) ? 0.15 : 0.0);
    ASSERT_EQ(watch.check(0.1 * k, {x, 1.0}, why), GoalWatch::Verdict::kPursuing) << k;
  }
  EXPECT_EQ(watch.check(5.1, {1.1, 1.0}, why), GoalWatch::Verdict::kStuck);
  EXPECT_NE(why.find("stuck: moved less than 0.2 m in 5 s"), std::string::npos) << why;
  // After a recovery progress counts from then on.
  watch.restartProgress(5.1, {1.1, 1.0});
  EXPECT_EQ(watch.check(9.0, {1.1, 1.0}, why), GoalWatch::Verdict::kPursuing);
  EXPECT_EQ(watch.check(10.2, {1.1, 1.0}, why), GoalWatch::Verdict::kStuck);
}

TEST(GoalWatch, ZeroTimeOutsNeverEndAGoal) {
  GoalWatch watch;  // timeout and oscillation_timeout 0
  watch.start(0.0, {0.0, 0.0});
  std::string why;
  EXPECT_EQ(watch.check(1e6, {0.0, 0.0}, why), GoalWatch::Verdict::kPursuing);
  EXPECT_DOUBLE_EQ(watch.elapsed(10.0), 10.0);
}

}  // namespace
}  // namespace jetbot_rl
