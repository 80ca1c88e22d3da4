// The motor model: dead zone, saturation and trim, on hand-computed values and in the physics.
#include "jetbot_rl/env/batched_env.h"
#include "randomization_test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

TEST(MotorModel, VelocityTargetOnHandComputedValues) {
  // duty = target / max; |duty| < dead zone -> 0; saturated at 1; times trim.
  EXPECT_DOUBLE_EQ(motorVelocityTarget(10.0, 20.0, 0.0, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(motorVelocityTarget(3.0, 20.0, 0.2, 1.0), 0.0);  // duty 0.15
  EXPECT_DOUBLE_EQ(motorVelocityTarget(-3.0, 20.0, 0.2, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(motorVelocityTarget(5.0, 20.0, 0.2, 1.0), 5.0);    // duty 0.25
  EXPECT_DOUBLE_EQ(motorVelocityTarget(30.0, 20.0, 0.0, 1.0), 20.0);  // saturated
  EXPECT_DOUBLE_EQ(motorVelocityTarget(-30.0, 20.0, 0.0, 1.0), -20.0);
  EXPECT_DOUBLE_EQ(motorVelocityTarget(10.0, 20.0, 0.0, 0.9), 9.0);
  EXPECT_DOUBLE_EQ(motorVelocityTarget(30.0, 20.0, 0.0, 0.9), 18.0);
}

/// Wheel speeds [rad/s] of env 0 after 60 steps at (left, right) targets.
std::pair<double, double> wheelSpeeds(const EnvConfig& c, float left, float right) {
  BatchedEnv env(jetbot(), c);
  speedAfter(env, 60, left, right);
  return {env.view(0).dofVelocity(0), env.view(0).dofVelocity(1)};
}

TEST(MotorModel, DeadZoneStopsSlowWheels) {
  EnvConfig c = smallConfig(1);
  c.motor.enabled = true;
  c.motor.dead_zone = {0.3, 0.3};
  EXPECT_NEAR(wheelSpeeds(smallConfig(1), 4.0f, 4.0f).first, 4.0, 0.2);  // without the model
  EXPECT_NEAR(wheelSpeeds(c, 4.0f, 4.0f).first, 0.0, 0.01);              // duty 0.2
  EXPECT_NEAR(wheelSpeeds(c, 8.0f, 8.0f).first, 8.0, 0.2);               // duty 0.4
  EXPECT_NEAR(wheelSpeeds(c, -8.0f, -4.0f).second, 0.0, 0.05);           // turning about it
}

TEST(MotorModel, SaturationCapsTheWheelSpeed) {
  EnvConfig c = smallConfig(1);
  c.motor.enabled = true;
  c.motor.max_wheel_speed = 12.0;  // [rad/s] at duty 1
  EXPECT_NEAR(wheelSpeeds(c, 20.0f, 20.0f).first, 12.0, 0.3);
  EXPECT_NEAR(wheelSpeeds(c, 6.0f, 6.0f).first, 6.0, 0.2);
  EXPECT_NEAR(wheelSpeeds(smallConfig(1), 20.0f, 20.0f).first, 20.0, 0.5);
}

TEST(MotorModel, TrimScalesTheWheelSpeed) {
  EnvConfig c = smallConfig(1);
  c.motor.enabled = true;
  c.motor.trim = {0.8, 0.8};
  const auto [left, right] = wheelSpeeds(c, 10.0f, 10.0f);
  EXPECT_NEAR(left, 8.0, 0.2);
  EXPECT_NEAR(right, 8.0, 0.2);
}

TEST(MotorModel, RangesPerDofSetEachSide) {
  // A robot whose right motor is 5 % weaker and whose left one stalls up to duty 0.3.
  EnvConfig c = smallConfig(4);
  c.motor.enabled = true;
  c.motor.trim = {1.0, 1.0, 0.95, 0.95};
  c.motor.dead_zone = {0.3, 0.3, 0.0, 0.0};
  BatchedEnv env(jetbot(), c);
  for (int e = 0; e < 4; ++e) {
    const RandomizationDraw r = env.view(e).randomization();
    EXPECT_EQ(r.motor_trim, (std::vector<double>{1.0, 0.95}));
    EXPECT_EQ(r.motor_dead_zone, (std::vector<double>{0.3, 0.0}));
  }
  // Duties 0.2 and 0.5: the left wheel stalls (dragged a little as the robot pivots about it,
  // against 4 rad/s without the model), the right one turns at 0.95 x its target (within the
  // few per cent a wheel lags in a turn).
  const auto [left, right] = wheelSpeeds(c, 4.0f, 10.0f);
  EXPECT_NEAR(left, 0.0, 0.5);
  EXPECT_NEAR(right, 9.5, 0.07 * 9.5);
  // A range per dof is drawn within its own bounds.
  c.motor.trim = {0.5, 0.6, 0.9, 1.0};
  c.motor.dead_zone = {0.0, 0.0};
  BatchedEnv drawn(jetbot(), c);
  for (int e = 0; e < 4; ++e) {
    const RandomizationDraw r = drawn.view(e).randomization();
    EXPECT_TRUE(r.motor_trim[0] >= 0.5 && r.motor_trim[0] <= 0.6) << r.motor_trim[0];
    EXPECT_TRUE(r.motor_trim[1] >= 0.9 && r.motor_trim[1] <= 1.0) << r.motor_trim[1];
  }
}

TEST(MotorModel, RangesForAnotherNumberOfDofsAreRefused) {
  EnvConfig c = smallConfig(1);
  c.motor.enabled = true;
  c.motor.trim = {0.9, 1.0, 0.9, 1.0, 0.9, 1.0};  // three pairs for two wheels
  try {
    BatchedEnv env(jetbot(), c);
    ADD_FAILURE() << "accepted three trim ranges for two dofs";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("motor_trim = [0.9, 1, 0.9, 1, 0.9, 1]"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("2 dofs: 4 values"), std::string::npos) << e.what();
  }
}

TEST(MotorModel, TrimsDrawnPerSideMakeTheRobotTurn) {
  EnvConfig c = smallConfig(16);
  c.motor.enabled = true;
  c.motor.trim = {0.7, 1.0};
  BatchedEnv env(jetbot(), c);
  for (int s = 0; s < 60; ++s) env.step(uniformActions(env, 10.0f, 10.0f));
  int turning = 0;
  for (int e = 0; e < 16; ++e) {
    const RandomizationDraw r = env.view(e).randomization();
    // In a turn the wheels track their targets within a few per cent (as without the model).
    EXPECT_NEAR(env.view(e).dofVelocity(0), 10.0 * r.motor_trim[0], 0.07 * 10.0 * r.motor_trim[0]);
    EXPECT_NEAR(env.view(e).dofVelocity(1), 10.0 * r.motor_trim[1], 0.07 * 10.0 * r.motor_trim[1]);
    // The weaker side is on the inside of the turn (counter-clockwise when the left is weaker).
    if (std::abs(r.motor_trim[0] - r.motor_trim[1]) > 0.05) {
      ++turning;
      const double yaw_rate = env.view(e).rootState().angular_velocity.z();
      EXPECT_EQ(yaw_rate > 0, r.motor_trim[0] < r.motor_trim[1]) << "env " << e;
    }
  }
  EXPECT_GT(turning, 8);
}

}  // namespace
}  // namespace jetbot_rl
