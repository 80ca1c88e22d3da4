// The dynamic window approach (issue 48's classical baseline): in the open it drives along its
// path at the window's speed; it keeps off a wall across its path by turning, never choosing a
// trajectory into it; boxed in, it turns in place towards the path; it stays within the dynamic
// window; min_vel_x above max_vel_x is refused naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/dwa_planner.h"

namespace jetbot_rl {
namespace {

DwaInput ahead(double speed) {
  DwaInput in;
  in.speed = speed;
  in.path = {{0.0, 0.0}, {3.0, 0.0}};
  in.local_goal = {2.0, 0.0};  // local_goal_distance along it
  return in;
}

TEST(DwaPlanner, InTheOpenItDrivesAlongItsPathAsFastAsTheWindowAllows) {
  const DwaConfig c;
  const DwaPlanner dwa(c, 0.1);
  const DwaCommand from_rest = dwa.plan(ahead(0.0));
  EXPECT_TRUE(from_rest.found);
  EXPECT_NEAR(from_rest.speed, c.acc_lim_x * c.sim_period, 1e-12);  // the window's top
  EXPECT_NEAR(from_rest.yaw_rate, 0.0, 0.2);
  const DwaCommand cruising = dwa.plan(ahead(0.6));
  EXPECT_NEAR(cruising.speed, 0.6, 1e-12);
}

TEST(DwaPlanner, AWallAcrossItsPathIsNeverDrivenInto) {
  DwaConfig c;
  const DwaPlanner dwa(c, 0.1);
  DwaInput in = ahead(0.6);
  for (double y = -1.0; y <= 1.0; y += 0.02) in.obstacles.emplace_back(0.5, y);
  const DwaCommand cmd = dwa.plan(in);
  // Whatever it picks keeps the footprint off the wall for sim_time.
  Eigen::Vector2d p = in.position;
  double yaw = 0.0;
  for (int k = 0; k < 170; ++k) {
    p += cmd.speed * 0.01 * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
    yaw += cmd.yaw_rate * 0.01;
    for (const Eigen::Vector2d& o : in.obstacles) ASSERT_GT((o - p).norm(), 0.1) << k;
  }
  EXPECT_LT(cmd.speed, 0.6);
}

TEST(DwaPlanner, BoxedInItTurnsInPlaceTowardsThePath) {
  // Returns inside the footprint all round: every trajectory, turning in place too, is refused.
  const DwaConfig c;
  const DwaPlanner dwa(c, 0.1);
  DwaInput in = ahead(0.0);
  in.yaw = -1.5;  // the path lies to its left
  for (int k = 0; k < 72; ++k) {
    const double a = k * 2.0 * 3.14159265358979 / 72;
    in.obstacles.emplace_back(0.09 * std::cos(a), 0.09 * std::sin(a));
  }
  const DwaCommand cmd = dwa.plan(in);
  EXPECT_FALSE(cmd.found);
  EXPECT_EQ(cmd.speed, 0.0);
  EXPECT_EQ(cmd.yaw_rate, c.max_vel_theta);
}

TEST(DwaPlanner, MinVelXAboveMaxVelXIsRefusedNamingIt) {
  DwaConfig c;
  c.min_vel_x = 0.8;
  try {
    checkFieldRules(c);
    ADD_FAILURE() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("dwa/min_vel_x"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace jetbot_rl
