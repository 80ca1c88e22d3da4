// urdfdom -> Bullet: the Jetbot loads, and every broken description names its link or joint.
#include "jetbot_rl/errors.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test fixture: '" << from << "' not in the URDF";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Expects constructing an env from `urdf` to throw ModelError mentioning `part`.
void expectModelError(const std::string& urdf, const std::string& part,
                      EnvConfig config = EnvConfig()) {
  config.num_envs = 1;
  try {
    BatchedEnv env(RobotModel::fromUrdfString(urdf), config);
    FAIL() << "no ModelError for " << part;
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(RobotModel, JetbotLoadsAsThreeBodies) {
  const auto model = jetbot();
  EXPECT_EQ(model->name(), "jetbot");
  ASSERT_EQ(model->bodies().size(), 3u);
  const BodyModel& base = model->bodies()[0];
  EXPECT_EQ(base.link_name, "base_link");
  ASSERT_EQ(base.links.size(), 2u);  // the caster is merged into the chassis
  EXPECT_EQ(base.links[1].name, "caster_link");
  EXPECT_NEAR(base.mass, 0.82, 1e-12);
  EXPECT_EQ(base.collisions.size(), 2u);
  EXPECT_NEAR(model->restHeight(), 0.03, 1e-9);
  const int left = model->bodyOfJoint("left_wheel_joint");
  ASSERT_GT(left, 0);
  EXPECT_EQ(model->bodies()[left].parent, 0);
  EXPECT_TRUE(model->bodies()[left].axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_DOUBLE_EQ(model->bodies()[left].velocity_limit, 20.0);
  EXPECT_DOUBLE_EQ(model->bodies()[left].effort_limit, 0.08);
  EXPECT_EQ(model->bodyOfJoint("caster_joint"), -1);  // fixed joints are not dofs
}

TEST(RobotModel, ItsVisibleTopCountsVisualsWithoutCollisionShapes) {
  // The chassis box (0.05 m tall, its centre 0.02 m above the axle, 0.03 m up) tops both.
  EXPECT_NEAR(jetbot()->visibleTop(), 0.03 + 0.02 + 0.025, 1e-9);
  // The scanner's housing has a visual only: a cylinder 0.04 m tall, 0.075 m above the axle.
  EXPECT_NEAR(test::lidarJetbot()->visibleTop(), 0.03 + 0.075 + 0.02, 1e-9);
}

TEST(RobotModel, MergedInertiaUsesTheParallelAxisTheorem) {
  const BodyModel& base = jetbot()->bodies()[0];
  // Chassis 0.8 kg at x = -0.03, caster 0.02 kg at x = -0.075: COM at their weighted mean.
  const double com_x = (0.8 * -0.03 + 0.02 * -0.075) / 0.82;
  EXPECT_NEAR(base.com_frame.translation().x(), com_x, 1e-12);
  const Eigen::Matrix3d inertia = base.com_frame.linear() * base.principal_inertia.asDiagonal() *
                                  base.com_frame.linear().transpose();
  const double dz_chassis = 0.02 - base.com_frame.translation().z();
  const double dx_chassis = -0.03 - com_x;
  const double expected_iyy =
      1.1267e-3 + 0.8 * (dx_chassis * dx_chassis + dz_chassis * dz_chassis) + 1.2903e-6 +
      0.02 *
          (std::pow(-0.075 - com_x, 2) + std::pow(-0.0173 - base.com_frame.translation().z(), 2));
  EXPECT_NEAR(inertia(1, 1), expected_iyy, 1e-12);
}

TEST(RobotModel, StringAndFileGiveTheSameModel) {
  const auto a = RobotModel::fromUrdfString(jetbotUrdfText());
  const auto b = jetbot();
  ASSERT_EQ(a->bodies().size(), b->bodies().size());
  for (size_t i = 0; i < a->bodies().size(); ++i) {
    EXPECT_EQ(a->bodies()[i].link_name, b->bodies()[i].link_name);
    EXPECT_EQ(a->bodies()[i].mass, b->bodies()[i].mass);
  }
}

TEST(RobotModel, MissingFileIsNamed) {
  EXPECT_THROW(RobotModel::fromUrdfFile("/nonexistent/jetbot.urdf"), ModelError);
}

TEST(RobotModel, MalformedXmlIsReported) {
  try {
    RobotModel::fromUrdfString("<robot name='x'><link name='a'></robot>");
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("could not be parsed"), std::string::npos) << e.what();
  }
}

TEST(RobotModel, MeshCollisionNamesTheLink) {
  expectModelError(
      replaced(jetbotUrdfText(),
               "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"1.5707963267948966 0 0\"/>\n      "
               "<geometry><cylinder radius=\"0.03\" length=\"0.025\"/></geometry>",
               "<collision>\n      <geometry><mesh "
               "filename=\"package://jetbot_rl/wheel.stl\"/></geometry>"),
      "link 'left_wheel': mesh 'package://jetbot_rl/wheel.stl'");  // and no resolver given
}

TEST(RobotModel, MissingInertialOnAMovingLinkNamesTheLink) {
  const std::string wheel_inertial =
      "<inertial>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <mass value=\"0.03\"/>\n     "
      " <!-- cylinder r = 0.03 m, h = 0.025 m, axis along y -->\n      <inertia ixx=\"8.3125e-6\" "
      "ixy=\"0\" ixz=\"0\" iyy=\"1.35e-5\" iyz=\"0\" izz=\"8.3125e-6\"/>\n    </inertial>";
  expectModelError(replaced(jetbotUrdfText(), wheel_inertial, ""), "link 'left_wheel'");
}

TEST(RobotModel, UnknownDofJointIsNamed) {
  EnvConfig config;
  config.dof_names = {"left_wheel_joint", "rear_wheel_joint"};
  expectModelError(jetbotUrdfText(), "joint 'rear_wheel_joint'", config);
  config.dof_names = {"left_wheel_joint", "caster_joint"};  // fixed: not drivable
  expectModelError(jetbotUrdfText(), "joint 'caster_joint'", config);
}

TEST(RobotModel, NonPositiveMassNamesTheLink) {
  expectModelError(replaced(jetbotUrdfText(), "<mass value=\"0.02\"/>", "<mass value=\"-0.02\"/>"),
                   "link 'caster_link': mass must be positive");
  expectModelError(replaced(jetbotUrdfText(), "<mass value=\"0.8\"/>", "<mass value=\"0\"/>"),
                   "link 'base_link': mass must be positive");
}

TEST(RobotModel, InvalidInertiaNamesTheLink) {
  // Violates the triangle inequality: izz > ixx + iyy.
  expectModelError(replaced(jetbotUrdfText(), "izz=\"1.3867e-3\"", "izz=\"1.0e-2\""),
                   "link 'base_link': invalid inertia");
  // Not positive definite.
  expectModelError(replaced(jetbotUrdfText(), "ixx=\"1.2903e-6\"", "ixx=\"-1.2903e-6\""),
                   "link 'caster_link': invalid inertia");
}

TEST(RobotModel, UnsupportedJointTypeNamesTheJoint) {
  expectModelError(
      replaced(jetbotUrdfText(), "<joint name=\"right_wheel_joint\" type=\"continuous\">",
               "<joint name=\"right_wheel_joint\" type=\"prismatic\">"),
      "joint 'right_wheel_joint': unsupported type");
}

TEST(RobotModel, DofWithoutVelocityLimitNamesTheJoint) {
  expectModelError(replaced(jetbotUrdfText(),
                            "<limit effort=\"0.08\" velocity=\"20.0\"/>\n  </joint>\n\n  <joint "
                            "name=\"right_wheel_joint\"",
                            "<limit effort=\"0.08\" velocity=\"0\"/>\n  </joint>\n\n  <joint "
                            "name=\"right_wheel_joint\""),
                   "joint 'left_wheel_joint': needs <limit velocity>");
}

}  // namespace
}  // namespace jetbot_rl
