// Differential-drive kinematics: the math, and radius, separation, sides and directions derived
// from both robots' URDFs, with an error naming the joint or link where they cannot be.
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

const std::vector<std::string> kJetbotDofs{"left_wheel_joint", "right_wheel_joint"};
const std::vector<std::string> kTribotDofs{"wheel_left_joint", "wheel_right_joint"};

DiffDrive jetbotDrive() {
  return DiffDrive(0.03, 0.1125, {"l", 0, 1.0, 20.0}, {"r", 1, 1.0, 20.0});
}

template <class Error, class F>
void expectError(F f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one naming " << parts.front();
  } catch (const Error& e) {
    for (const auto& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  }
}

TEST(DiffDrive, StraightDrivingTurnsBothWheelsAtSpeedOverRadius) {
  const auto t = jetbotDrive().wheelTargets({0.3, 0.0});
  EXPECT_DOUBLE_EQ(t[0], 10.0);
  EXPECT_DOUBLE_EQ(t[1], 10.0);
}

TEST(DiffDrive, TurningInPlaceTurnsTheWheelsOppositeWays) {
  const double omega = 2.0;  // [rad/s], counter-clockwise: the right wheel forward
  const auto t = jetbotDrive().wheelTargets({0.0, omega});
  const double rim = omega * 0.1125 / 2 / 0.03;
  EXPECT_DOUBLE_EQ(t[0], -rim);
  EXPECT_DOUBLE_EQ(t[1], rim);
}

TEST(DiffDrive, TargetsBeyondTheLimitAreScaledTogetherKeepingTheCurvature) {
  const DiffDrive drive = jetbotDrive();
  const PlanarTwist wanted{1.0, 2.0};  // 33 and 37 rad/s: both beyond 20 rad/s
  const auto t = drive.wheelTargets(wanted);
  EXPECT_NEAR(std::max(std::abs(t[0]), std::abs(t[1])), 20.0, 1e-12);
  const PlanarTwist got = drive.bodyTwist(t);
  EXPECT_LT(got.linear, wanted.linear);
  EXPECT_NEAR(got.angular / got.linear, wanted.angular / wanted.linear, 1e-12);
  // A turn in place beyond the limit stays a turn in place.
  const auto spin = drive.wheelTargets({0.0, 100.0});
  EXPECT_NEAR(spin[1], 20.0, 1e-12);
  EXPECT_NEAR(spin[0], -20.0, 1e-12);
}

TEST(DiffDrive, TheTighterWheelLimitScalesBoth) {
  const DiffDrive drive(0.03, 0.1125, {"l", 0, 1.0, 20.0}, {"r", 1, 1.0, 5.0});
  const auto t = drive.wheelTargets({0.3, 0.0});
  EXPECT_NEAR(t[0], 5.0, 1e-12);
  EXPECT_NEAR(t[1], 5.0, 1e-12);
}

TEST(DiffDrive, BodyTwistInvertsWheelTargets) {
  const DiffDrive drive = jetbotDrive();
  for (const PlanarTwist& twist : {PlanarTwist{0.2, 0.0}, PlanarTwist{-0.1, 1.5},
                                   PlanarTwist{0.0, -3.0}, PlanarTwist{0.25, -0.7}}) {
    const PlanarTwist back = drive.bodyTwist(drive.wheelTargets(twist));
    EXPECT_NEAR(back.linear, twist.linear, 1e-12);
    EXPECT_NEAR(back.angular, twist.angular, 1e-12);
  }
}

TEST(DiffDrive, DirectionsAndDofOrderAreFollowed) {
  // Left wheel is dof 1 and turns backwards to drive forward (its axis points right).
  const DiffDrive drive(0.03, 0.1125, {"l", 1, -1.0, 20.0}, {"r", 0, 1.0, 20.0});
  const auto t = drive.wheelTargets({0.3, 0.0});
  EXPECT_DOUBLE_EQ(t[1], -10.0);
  EXPECT_DOUBLE_EQ(t[0], 10.0);
  const PlanarTwist back = drive.bodyTwist(t);
  EXPECT_NEAR(back.linear, 0.3, 1e-12);
  EXPECT_NEAR(back.angular, 0.0, 1e-12);
}

TEST(DiffDrive, NonFiniteTwistIsRejected) {
  expectError<InputError>([] { jetbotDrive().wheelTargets({std::nan(""), 0.0}); }, {"nan"});
  expectError<InputError>([] { jetbotDrive().wheelTargets({0.0, INFINITY}); }, {"inf"});
}

TEST(DiffDrive, InvalidValuesAreNamed) {
  expectError<ConfigError>(
      [] {
        DiffDrive(0.0, 0.1, {"l", 0, 1, 1}, {"r", 1, 1, 1});
      },
      {"wheel_radius = 0"});
  expectError<ConfigError>(
      [] {
        DiffDrive(0.03, -0.1, {"l", 0, 1, 1}, {"r", 1, 1, 1});
      },
      {"wheel_separation = -0.1"});
  expectError<ConfigError>(
      [] {
        DiffDrive(0.03, 0.1, {"l", 0, 1, 0}, {"r", 1, 1, 1});
      },
      {"wheel_velocity_limit = 0", "'l'"});
  expectError<ConfigError>(
      [] {
        DiffDrive(0.03, 0.1, {"l", 0, 1, 1}, {"r", 0, 1, 1});
      },
      {"dofs 0 and 1"});
}

TEST(DiffDriveDerivation, JetbotMatchesIsaacSimsController) {
  const DiffDrive drive = DiffDrive::fromRobot(*jetbot(), kJetbotDofs, {20.0, 20.0});
  EXPECT_NEAR(drive.wheelRadius(), 0.03, 1e-12);
  EXPECT_NEAR(drive.wheelSeparation(), 0.1125, 1e-12);
  EXPECT_EQ(drive.left().joint, "left_wheel_joint");
  EXPECT_EQ(drive.left().dof, 0);
  EXPECT_EQ(drive.right().joint, "right_wheel_joint");
  EXPECT_EQ(drive.left().direction, 1.0);
  EXPECT_EQ(drive.right().direction, 1.0);
  EXPECT_NE(drive.radiusSource().find("URDF"), std::string::npos);
  EXPECT_NE(drive.describe().find("wheel_radius 0.03 m"), std::string::npos) << drive.describe();
  EXPECT_NE(drive.describe().find("wheel_separation 0.1125 m"), std::string::npos);
}

TEST(DiffDriveDerivation, LeftIsFoundWhateverTheDofOrder) {
  const DiffDrive drive =
      DiffDrive::fromRobot(*jetbot(), {"right_wheel_joint", "left_wheel_joint"}, {20.0, 20.0});
  EXPECT_EQ(drive.left().joint, "left_wheel_joint");
  EXPECT_EQ(drive.left().dof, 1);
  EXPECT_EQ(drive.right().dof, 0);
}

TEST(DiffDriveDerivation, TribotWithRotatedWheelFrames) {
  const DiffDrive drive = DiffDrive::fromRobot(*tribot(), kTribotDofs, {8.0, 8.0});
  EXPECT_NEAR(drive.wheelRadius(), 0.033, 1e-9);
  EXPECT_NEAR(drive.wheelSeparation(), 0.16, 1e-6);  // along the axis, tilted by 0.0008 rad
  EXPECT_EQ(drive.left().joint, "wheel_left_joint");
  // rpy="-1.57 0 0" turns the joint's z (the axis) onto +y: positive drives forward.
  EXPECT_EQ(drive.left().direction, 1.0);
  EXPECT_EQ(drive.right().direction, 1.0);
}

TEST(DiffDriveDerivation, AnAxisPointingRightTurnsBackwardsToDriveForward) {
  std::string urdf = tribotUrdfText();
  for (int i = 0; i < 2; ++i)
    urdf = replaceOnce(urdf, "<axis xyz=\"0 0 1\"/>", "<axis xyz=\"0 0 -1\"/>");
  const DiffDrive drive =
      DiffDrive::fromRobot(*RobotModel::fromUrdfString(urdf, testResolver), kTribotDofs, {8, 8});
  EXPECT_EQ(drive.left().direction, -1.0);
  EXPECT_EQ(drive.right().direction, -1.0);
  EXPECT_NEAR(drive.wheelTargets({0.033, 0.0})[0], -1.0, 1e-12);
}

TEST(DiffDriveDerivation, ParametersOverrideTheUrdf) {
  EnvConfig config = tribotConfig(1);
  config.wheel_radius = 0.05;
  config.wheel_separation = 0.2;
  BatchedEnv env(tribot(), config);
  const DiffDrive drive = DiffDrive::fromEnv(env);
  EXPECT_DOUBLE_EQ(drive.wheelRadius(), 0.05);
  EXPECT_DOUBLE_EQ(drive.wheelSeparation(), 0.2);
  EXPECT_EQ(drive.radiusSource(), "parameter");
  EXPECT_DOUBLE_EQ(drive.left().velocity_limit, 8.0);  // the limit in use (a parameter here)
}

TEST(DiffDriveDerivation, AMeshWheelRollsOnItsFarthestVertex) {
  // A 24-sided prism of radius 0.033 m about z, the joint axis of the tribot's wheels.
  std::ostringstream obj;
  obj.precision(17);
  const int sides = 24;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * M_PI * k / sides;
    for (double z : {-0.009, 0.009})
      obj << "v " << 0.033 * std::cos(a) << " " << 0.033 * std::sin(a) << " " << z << "\n";
  }
  for (int k = 0; k < sides; ++k) {
    const int a = 2 * k + 1, b = 2 * k + 2, c = 2 * ((k + 1) % sides) + 1, d = c + 1;
    obj << "f " << a << " " << c << " " << d << "\nf " << a << " " << d << " " << b << "\n";
  }
  const std::string path = writeTempFile("wheel.obj", obj.str());
  std::string urdf = tribotUrdfText();
  for (int i = 0; i < 2; ++i) {
    urdf = replaceOnce(urdf,
                       "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      "
                       "<geometry><cylinder radius=\"0.033\" length=\"0.018\"/>",
                       "<collision>\n      <geometry><mesh filename=\"file://" + path + "\"/>");
  }
  const auto model = RobotModel::fromUrdfString(urdf, testResolver);
  const DiffDrive drive = DiffDrive::fromRobot(*model, kTribotDofs, {8.0, 8.0});
  EXPECT_NEAR(drive.wheelRadius(), 0.033, 1e-9);
  EXPECT_NEAR(model->restHeight(), 0.0, 1e-4);  // the mesh wheels stand on the ground
}

TEST(DiffDriveDerivation, ErrorsNameTheJointOrLink) {
  // Not two dofs.
  expectError<ConfigError>([] { DiffDrive::fromRobot(*jetbot(), {"left_wheel_joint"}, {20.0}); },
                           {"dof_names"});
  // A wheel with only a box to roll on.
  const std::string boxed = replaceOnce(
      jetbotUrdfText(),
      "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"1.5707963267948966 0 0\"/>\n      "
      "<geometry><cylinder radius=\"0.03\" length=\"0.025\"/></geometry>",
      "<collision>\n      <geometry><box size=\"0.06 0.025 0.06\"/></geometry>");
  expectError<ModelError>(
      [&] {
        DiffDrive::fromRobot(*RobotModel::fromUrdfString(boxed), kJetbotDofs, {20, 20});
      },
      {"joint 'left_wheel_joint'", "link 'left_wheel'", "wheel_radius"});
  // ... which a wheel_radius parameter makes drivable.
  EXPECT_NO_THROW(
      DiffDrive::fromRobot(*RobotModel::fromUrdfString(boxed), kJetbotDofs, {20, 20}, 0.03));
  // Wheels of different radii.
  const std::string odd = replaceOnce(
      jetbotUrdfText(),
      "<origin xyz=\"0 0 0\" rpy=\"1.5707963267948966 0 0\"/>\n      "
      "<geometry><cylinder radius=\"0.03\" length=\"0.025\"/></geometry>\n    </collision>",
      "<origin xyz=\"0 0 0\" rpy=\"1.5707963267948966 0 0\"/>\n      "
      "<geometry><cylinder radius=\"0.035\" length=\"0.025\"/></geometry>\n    </collision>");
  expectError<ModelError>(
      [&] {
        DiffDrive::fromRobot(*RobotModel::fromUrdfString(odd), kJetbotDofs, {20, 20});
      },
      {"joint 'left_wheel_joint'", "right_wheel_joint", "wheel_radius"});
  // An axis along x is no differential drive.
  const std::string steered =
      replaceOnce(jetbotUrdfText(), "<axis xyz=\"0 1 0\"/>", "<axis xyz=\"1 0 0\"/>");
  expectError<ModelError>(
      [&] {
        DiffDrive::fromRobot(*RobotModel::fromUrdfString(steered), kJetbotDofs, {20, 20});
      },
      {"joint 'left_wheel_joint'", "axis"});
  // Both wheels on one side: left cannot be told from right.
  const std::string stacked = replaceOnce(jetbotUrdfText(), "<origin xyz=\"0 -0.05625 0\"",
                                          "<origin xyz=\"0.05 0.05625 0\"");
  expectError<ModelError>(
      [&] {
        DiffDrive::fromRobot(*RobotModel::fromUrdfString(stacked), kJetbotDofs, {20, 20});
      },
      {"'left_wheel_joint'", "'right_wheel_joint'", "left wheel"});
}

}  // namespace
}  // namespace jetbot_rl
