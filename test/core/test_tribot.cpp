// The second robot (urdf/examples/tribot.urdf) driven through the differential-drive kinematics, as
// cmd_vel drives it: straight at r * omega, in place at 2 omega r / separation, parked still.
#include <cmath>

#include "jetbot_rl/robot/diff_drive.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using test::tribot;
using test::tribotConfig;

constexpr double kTribotWheelRadius = 0.033;     // [m]
constexpr double kTribotWheelSeparation = 0.16;  // [m]

using test::Averages;

/// Drives `twist` through DiffDrive for `settle` steps, then averages over `measure` steps.
Averages drive(BatchedEnv& env, const DiffDrive& kinematics, const PlanarTwist& twist, int settle,
               int measure) {
  const auto targets = kinematics.wheelTargets(twist);
  return test::drive(env, static_cast<float>(targets[0]), static_cast<float>(targets[1]), settle,
                     measure);
}

class Tribot : public ::testing::Test {
 protected:
  BatchedEnv env{tribot(), tribotConfig(1)};
  DiffDrive kinematics = DiffDrive::fromEnv(env);
};

TEST_F(Tribot, DrivesStraightAtWheelSpeedTimesRadius) {
  const double omega = 5.0;  // [rad/s] of the wheels
  const double expected = omega * kTribotWheelRadius;
  const Averages avg = drive(env, kinematics, {expected, 0.0}, 120, 60);
  EXPECT_NEAR(avg.body_velocity.x(), expected, 0.05 * expected);
  EXPECT_NEAR(avg.body_velocity.y(), 0.0, 0.01);
  EXPECT_NEAR(avg.yaw_rate, 0.0, 0.05);
  // Odometry from the wheel speeds agrees.
  const PlanarTwist odom =
      kinematics.bodyTwist({env.view(0).dofVelocity(0), env.view(0).dofVelocity(1)});
  EXPECT_NEAR(odom.linear, expected, 0.01 * expected);
}

TEST_F(Tribot, DrivesBackwards) {
  const Averages avg = drive(env, kinematics, {-5.0 * kTribotWheelRadius, 0.0}, 120, 60);
  EXPECT_NEAR(avg.body_velocity.x(), -5.0 * kTribotWheelRadius, 0.05 * 5.0 * kTribotWheelRadius);
}

TEST_F(Tribot, TurnsInPlaceAtTwiceWheelRimSpeedOverSeparation) {
  const double omega = 5.0;  // [rad/s] of the wheels
  const double expected =
      2.0 * omega * kTribotWheelRadius / kTribotWheelSeparation;  // 2.06 rad/s, CCW
  const auto targets = kinematics.wheelTargets({0.0, expected});
  EXPECT_NEAR(targets[0], -omega, 1e-5);  // the separation is along the axis, tilted 0.0008 rad
  EXPECT_NEAR(targets[1], omega, 1e-5);
  const Averages avg = drive(env, kinematics, {0.0, expected}, 60, 60);
  EXPECT_NEAR(avg.yaw_rate, expected, 0.10 * expected);
}

TEST_F(Tribot, KeepsTheCurvatureBeyondTheWheelLimit) {
  const PlanarTwist wanted{1.0, 2.0};  // far beyond 8 rad/s: scaled down to a 0.5 m radius turn
  const Averages avg = drive(env, kinematics, wanted, 120, 60);
  const double speed = avg.body_velocity.x();
  EXPECT_GT(speed, 0.1);
  // The COM is 3 cm behind the axle: its forward speed is the axle's, its yaw rate the body's.
  EXPECT_NEAR(avg.yaw_rate / speed, wanted.angular / wanted.linear, 0.1 * 2.0);
}

TEST_F(Tribot, ParkedStandsStill) {
  drive(env, kinematics, {0.15, 1.0}, 60, 1);
  const Averages parked = drive(env, kinematics, {0.0, 0.0}, 120, 60);
  EXPECT_LT(parked.body_velocity.norm(), 1e-4);
  EXPECT_LT(std::abs(parked.yaw_rate), 1e-3);
}

TEST(TribotVelocityTask, RandomTargetsForTwoEpisodesStaySane) {
  BatchedEnv env(tribot(), tribotConfig(8));
  double worst_joint_error = 0.0;
  for (int s = 0; s < 2 * env.maxEpisodeLength(); ++s) {
    const auto& r = env.step(test::randomActions(env.numEnvs(), s));
    ASSERT_TRUE(r.divergences.empty()) << r.divergences[0].reason;
    for (float reward : r.rewards) ASSERT_TRUE(std::isfinite(reward));
    worst_joint_error = std::max(worst_joint_error, env.view(s % env.numEnvs()).maxJointError());
  }
  EXPECT_LT(worst_joint_error, 1e-3);
  EXPECT_EQ(env.divergedCount(), 0u);
}

}  // namespace
}  // namespace jetbot_rl
