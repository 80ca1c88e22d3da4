// Driving accuracy of the Jetbot against differential-drive kinematics.
#include <cmath>

#include "test_util.h"

namespace jetbot_rl {
namespace {

using test::Averages;
using test::drive;
using test::jetbot;
using test::smallConfig;
using test::uniformActions;

TEST(Kinematics, StraightDrivingReachesWheelSpeedTimesRadius) {
  BatchedEnv env(jetbot(), smallConfig(1));
  const Averages avg = drive(env, 10.0f, 10.0f, 120, 60);
  const double expected = 10.0 * test::kJetbotWheelRadius;  // 0.30 m/s
  EXPECT_NEAR(avg.body_velocity.x(), expected, 0.05 * expected);
  EXPECT_NEAR(avg.body_velocity.y(), 0.0, 0.01);
  EXPECT_NEAR(avg.body_velocity.z(), 0.0, 0.01);
  EXPECT_NEAR(avg.yaw_rate, 0.0, 0.05);
}

TEST(Kinematics, ReverseDrivingIsSymmetric) {
  BatchedEnv env(jetbot(), smallConfig(1));
  const Averages avg = drive(env, -10.0f, -10.0f, 120, 60);
  EXPECT_NEAR(avg.body_velocity.x(), -0.30, 0.015);
}

TEST(Kinematics, TurningInPlaceMatchesDifferentialDrive) {
  BatchedEnv env(jetbot(), smallConfig(1));
  const float w = 10.0f;
  const Averages avg = drive(env, -w, w, 60, 60);
  const double expected_yaw_rate =
      2.0 * w * test::kJetbotWheelRadius / test::kJetbotWheelSeparation;  // CCW positive
  EXPECT_NEAR(avg.yaw_rate, expected_yaw_rate, 0.10 * expected_yaw_rate);
  // Near zero: within 10 % of the wheels' rim speed (0.3 m/s).
  EXPECT_NEAR(avg.body_velocity.x(), 0.0, 0.1 * w * test::kJetbotWheelRadius);
}

TEST(Kinematics, AParkedRobotStandsStill) {
  BatchedEnv env(jetbot(), smallConfig(1));
  drive(env, 15.0f, 10.0f, 60, 1);
  const Averages parked = drive(env, 0.0f, 0.0f, 120, 60);
  EXPECT_LT(parked.body_velocity.norm(), 1e-4);  // no creep
  EXPECT_LT(std::abs(parked.yaw_rate), 1e-3);
}

TEST(Kinematics, TargetsBeyondTheLimitAreClamped) {
  BatchedEnv env(jetbot(), smallConfig(1));
  ASSERT_FLOAT_EQ(env.actionHigh()[0], 20.0f);
  const Averages avg = drive(env, 1000.0f, 1000.0f, 120, 60);
  EXPECT_NEAR(avg.body_velocity.x(), 20.0 * test::kJetbotWheelRadius,
              0.05 * 20.0 * test::kJetbotWheelRadius);
  EXPECT_LE(env.view(0).dofVelocity(0), 20.0 * 1.02);
}

TEST(Kinematics, WheelsStayOnTheChassisThroughReversals) {
  EnvConfig config = smallConfig(1);
  config.episode_length_s = 20.0;  // one uninterrupted episode
  BatchedEnv env(jetbot(), config);
  const int steps = static_cast<int>(10.0 / env.controlDt());  // 10 s
  double worst = 0.0;
  for (int s = 0; s < steps; ++s) {
    // Full speed, reversing every 0.5 s, with every other half second spent turning.
    const float sign = (s / 30) % 2 ? -1.0f : 1.0f;
    const bool turn = (s / 60) % 2;
    const float left = sign * 20.0f, right = turn ? -left : left;
    env.step(uniformActions(env, left, right));
    worst = std::max(worst, env.view(0).maxJointError());
  }
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace jetbot_rl
