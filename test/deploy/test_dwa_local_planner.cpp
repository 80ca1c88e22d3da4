// The deploy node's classical baseline (local_planner dwa) without a master: a LaserScan's returns
// placed from the robot's pose in the odometry frame as the benchmark's DWA gets its simulated
// returns (REP 117's infinities and NaN), the straight line to the goal without a plan, the plan
// and its local goal with one, and the steps without a clear trajectory counted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "jetbot_rl/ros/deploy/dwa_local_planner.h"

namespace jetbot_rl {
namespace {

constexpr float kBeyond = std::numeric_limits<float>::infinity();
constexpr double kFootprint = 0.1;

/// The robot at (1, 2) heading `yaw`, standing.
MeasuredState robotAt(double yaw, const Eigen::Vector2d& goal) {
  MeasuredState s;
  s.root.position = {1.0, 2.0, 0.0};
  s.root.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  s.goal = goal;
  return s;
}

/// A scan of `n` beams over [-pi/2, pi/2] reading `range` each, range [0.05, 3] m.
sensor_msgs::LaserScan scanOf(int n, float range) {
  sensor_msgs::LaserScan s;
  s.angle_min = static_cast<float>(-M_PI / 2);
  s.angle_increment = static_cast<float>(M_PI / (n - 1));
  s.angle_max = static_cast<float>(M_PI / 2);
  s.range_min = 0.05f;
  s.range_max = 3.0f;
  s.ranges.assign(n, range);
  return s;
}

/// The DWA's command on `in` (what the deploy planner must give for the same scene).
DwaCommand direct(const DwaInput& in) { return DwaPlanner(DwaConfig(), kFootprint).plan(in); }

TEST(DwaLocalPlanner, DrivesAsTheBenchmarksDwaOnTheSameReturnsAndWay) {
  const double yaw = 0.7;
  const Eigen::Vector2d goal(3.0, 4.0);
  MeasuredState state = robotAt(yaw, goal);
  sensor_msgs::LaserScan scan = scanOf(5, kBeyond);          // nothing in range ...
  scan.ranges[1] = 0.6f;                                     // ... but a return at -45 deg
  scan.ranges[2] = -kBeyond;                                 // too close ahead: at range_min
  scan.ranges[3] = std::numeric_limits<float>::quiet_NaN();  // none
  scan.ranges[4] = 3.5f;                                     // beyond range_max: none
  DwaLocalPlanner planner(DwaConfig(), kFootprint);
  const PlanarTwist twist = planner.step(state, scan, {}, Eigen::Vector2d::Zero());

  DwaInput in;
  in.position = {1.0, 2.0};
  in.yaw = yaw;
  in.path = {in.position, goal};
  // The goal 2.83 m away: the local goal local_goal_distance (2 m) along the line.
  in.local_goal = in.position + 2.0 * (goal - in.position).normalized();
  in.obstacles = {
      in.position + 0.6 * Eigen::Vector2d(std::cos(yaw - M_PI / 4), std::sin(yaw - M_PI / 4)),
      in.position + 0.05 * Eigen::Vector2d(std::cos(yaw), std::sin(yaw))};
  const DwaCommand expected = direct(in);
  EXPECT_NEAR(twist.linear, expected.speed, 1e-12);
  EXPECT_NEAR(twist.angular, expected.yaw_rate, 1e-12);
  // Something at range_min ahead blocks every trajectory: a turn in place, counted.
  EXPECT_FALSE(expected.found);
  EXPECT_EQ(planner.blockedSteps(), 1);

  // Without the return ahead: the way is clear, it drives forward towards the goal.
  scan.ranges[2] = kBeyond;
  const PlanarTwist clear = planner.step(state, scan, {}, Eigen::Vector2d::Zero());
  EXPECT_GT(clear.linear, 0.0);
  EXPECT_EQ(planner.blockedSteps(), 1);
  in.obstacles.pop_back();
  EXPECT_NEAR(clear.angular, direct(in).yaw_rate, 1e-12);
}

TEST(DwaLocalPlanner, FollowsThePlanAndItsLocalGoalWhenThereIsOne) {
  // The goal straight ahead, the plan (odometry frame) bending left first: the DWA turns left.
  MeasuredState state = robotAt(0.0, {3.0, 2.0});
  const std::vector<Eigen::Vector2d> plan{{1.0, 2.0}, {1.0, 3.0}, {3.0, 3.0}, {3.0, 2.0}};
  DwaLocalPlanner planner(DwaConfig(), kFootprint);
  const sensor_msgs::LaserScan empty = scanOf(5, kBeyond);
  const PlanarTwist along_plan = planner.step(state, empty, plan, {1.0, 3.0});
  const PlanarTwist straight = planner.step(state, empty, {}, Eigen::Vector2d::Zero());
  // From standing, the window reaches 0.16 rad/s either way (acc_lim_theta x sim_period).
  EXPECT_GT(along_plan.angular, 0.1);
  EXPECT_LT(std::abs(straight.angular), 0.02);
  EXPECT_GT(straight.linear, 0.0);
  EXPECT_EQ(planner.blockedSteps(), 0);
}

}  // namespace
}  // namespace jetbot_rl
