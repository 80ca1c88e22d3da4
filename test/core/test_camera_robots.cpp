// The robots as cameras see them: the URDF's visuals with their materials in the robot model,
// bad visuals named, the robot's own body seen from its camera (without the camera's own
// housing), and the other robots of a world by their visuals, where geometry puts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "camera_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "sensors/camera_robot.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

std::string cameraJetbotText() {
  std::ifstream file(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

const VisualGeometry& visualOf(const RobotModel& robot, const std::string& link) {
  for (const BodyModel& body : robot.bodies()) {
    for (const VisualGeometry& v : body.visuals) {
      if (v.link == link) return v;
    }
  }
  throw std::runtime_error("no visual of link " + link);
}

/// Where the ray from `origin` along unit `dir` enters the box of `half` extents centred on
/// `centre` in `frame` (+inf: it misses).
double rayIntoBox(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                  const Eigen::Isometry3d& frame, const Eigen::Vector3d& centre,
                  const Eigen::Vector3d& half) {
  const Eigen::Vector3d o = frame.inverse() * origin - centre;
  const Eigen::Vector3d d = frame.linear().transpose() * dir;
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double a = (-half[k] - o[k]) / d[k], b = (half[k] - o[k]) / d[k];
    enter = std::max(enter, std::min(a, b));
    leave = std::min(leave, std::max(a, b));
  }
  return enter <= leave ? enter : std::numeric_limits<double>::infinity();
}

TEST(CameraRobots, TheUrdfsVisualsWithTheirMaterials) {
  const RobotModelConstPtr robot = RobotModel::fromUrdfString(cameraJetbotText());
  const VisualGeometry& chassis = visualOf(*robot, "base_link");
  EXPECT_EQ(chassis.shape.type, CollisionGeometry::Type::kBox);
  EXPECT_TRUE(chassis.shape.size.isApprox(Eigen::Vector3d(0.12, 0.08, 0.05)));
  EXPECT_TRUE(chassis.shape.origin.translation().isApprox(Eigen::Vector3d(-0.03, 0.0, 0.02)));
  EXPECT_TRUE(chassis.colour.isApprox(Eigen::Vector3f(0.46f, 0.73f, 0.0f)));
  // Merged by its fixed joint into the chassis body, placed by it.
  const VisualGeometry& camera = visualOf(*robot, "camera_link");
  EXPECT_TRUE(camera.shape.origin.translation().isApprox(Eigen::Vector3d(0.045, 0.0, 0.06)));
  EXPECT_EQ(visualOf(*robot, "caster_link").shape.type, CollisionGeometry::Type::kSphere);
  // A material named at its first use and referred to by name after it.
  EXPECT_TRUE(visualOf(*robot, "right_wheel").colour.isApprox(Eigen::Vector3f(0.1f, 0.1f, 0.1f)));
  EXPECT_EQ(visualOf(*robot, "right_wheel").shape.type, CollisionGeometry::Type::kCylinder);
}

TEST(CameraRobots, BadVisualsAreNamedAndAnUnreadableMeshOnlyWhereACameraDrawsIt) {
  try {
    RobotModel::fromUrdfString(test::replaceOnce(
        cameraJetbotText(), "<box size=\"0.12 0.08 0.05\"/>", "<box size=\"0.12 -0.08 0.05\"/>"));
    ADD_FAILURE() << "a negative visual size accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("base_link"), std::string::npos) << e.what();
  }
  const std::string mesh_urdf =
      test::replaceOnce(cameraJetbotText(), "<box size=\"0.01 0.025 0.025\"/>",
                        "<mesh filename=\"package://nowhere/camera.stl\"/>");
  const RobotModelConstPtr robot = RobotModel::fromUrdfString(mesh_urdf);  // no camera: loads
  EnvConfig c = test::smallConfig(1);
  c.camera.width = 8;
  c.camera.height = 8;
  try {
    BatchedEnv env(robot, c);
    ADD_FAILURE() << "a camera drew a mesh it cannot read";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("camera_link"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("package://nowhere/camera.stl"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("camera/robot_visuals"), std::string::npos) << e.what();
  }
  c.camera.robot_visuals = false;  // the way out it names: no robot drawn
  EXPECT_NO_THROW(BatchedEnv(robot, c));
  c.camera.enabled = false;
  EXPECT_NO_THROW(BatchedEnv(robot, c));
}

TEST(CameraRobots, ACameraSeesItsOwnBodyButNotItsHousing) {
  // A camera 0.3 m above the chassis looking straight down, in a 3 cm housing of its own.
  const std::string urdf = test::replaceOnce(cameraJetbotText(), "</robot>", R"(
  <link name="overhead_camera">
    <visual><geometry><box size="0.03 0.03 0.03"/></geometry></visual>
  </link>
  <joint name="overhead_joint" type="fixed">
    <parent link="base_link"/>
    <child link="overhead_camera"/>
    <origin xyz="-0.03 0 0.3" rpy="0 1.5707963267948966 0"/>
  </joint>
</robot>)");
  EnvConfig c = test::smallConfig(1);
  c.camera.link = "overhead_camera";
  c.camera.width = 33;
  c.camera.height = 33;
  c.camera.horizontal_fov = 0.6;
  c.camera.images = {"rgb", "depth", "label"};
  BatchedEnv env(RobotModel::fromUrdfString(urdf), c);
  const EnvImages images = env.view(0).images();
  const int centre = 16 * 33 + 16;
  EXPECT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kRobot));
  // The chassis' top, 0.045 m above base_link: 0.255 m below the camera.
  EXPECT_NEAR(images.depth[centre], 0.255, 1e-3);
  const std::uint8_t* rgb = images.rgb + 3 * centre;
  EXPECT_GT(rgb[1], rgb[0]);  // jetbot_green
  EXPECT_GT(rgb[1], rgb[2]);
  int robot = 0, ground = 0;
  for (int i = 0; i < 33 * 33; ++i) {
    robot += images.label[i] == static_cast<std::uint8_t>(SurfaceClass::kRobot);
    ground += images.label[i] == static_cast<std::uint8_t>(SurfaceClass::kGround);
  }
  EXPECT_GT(robot, 100);
  EXPECT_GT(ground, 100);
}

TEST(CameraRobots, TheOtherRobotsOfAWorldAreSeenByTheirVisuals) {
  EnvConfig c = test::smallConfig(1);
  c.world.arena_size = {4.0, 4.0};
  c.world.random_start = true;
  c.team.robots_per_env = 2;
  c.camera.width = 33;
  c.camera.height = 33;
  c.camera.noise_std = 0.0;
  c.camera.update_every = 1;
  c.camera.images = {"rgb", "depth", "label"};
  BatchedEnv env(RobotModel::fromUrdfString(cameraJetbotText()), c);
  ASSERT_EQ(env.numEnvs(), 2);
  // Row 1 stands 0.4 m ahead of row 0, both facing +x: row 0's camera looks at its back.
  RootState state = env.view(0).rootState();
  state.orientation = Eigen::Quaterniond::Identity();
  state.com_linear_velocity.setZero();
  state.angular_velocity.setZero();
  state.position.head<2>() = Eigen::Vector2d(-0.5, 0.0);
  env.setRootState(0, state);
  state.position.x() += 0.4;
  env.setRootState(1, state);
  env.step(std::vector<float>(4, 0.0f));
  const EnvImages images = env.view(0).images();
  const int centre = 16 * 33 + 16;
  ASSERT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kRobot));
  const Eigen::Isometry3d camera = env.view(0).cameraPose();
  const RootState other = env.view(1).rootState();
  Eigen::Isometry3d other_frame = Eigen::Isometry3d::Identity();
  other_frame.translation() = other.position;
  other_frame.linear() = other.orientation.toRotationMatrix();
  const double expected =
      rayIntoBox(camera.translation(), camera.linear().col(2), other_frame,
                 Eigen::Vector3d(-0.03, 0.0, 0.02), Eigen::Vector3d(0.06, 0.04, 0.025));
  ASSERT_TRUE(std::isfinite(expected));
  EXPECT_NEAR(images.depth[centre], expected, 2e-3);
  const std::uint8_t* rgb = images.rgb + 3 * centre;
  EXPECT_GT(rgb[1], rgb[0]);
  // Row 1 sees no robot ahead (row 0 is behind it).
  const EnvImages behind = env.view(1).images();
  EXPECT_NE(behind.label[centre], static_cast<std::uint8_t>(SurfaceClass::kRobot));
  // Without robot visuals the other robot is the scanner's cylinder, a mover.
  c.camera.robot_visuals = false;
  BatchedEnv plain(RobotModel::fromUrdfString(cameraJetbotText()), c);
  state.position.x() -= 0.4;
  plain.setRootState(0, state);
  state.position.x() += 0.4;
  plain.setRootState(1, state);
  plain.step(std::vector<float>(4, 0.0f));
  EXPECT_EQ(plain.view(0).images().label[centre], static_cast<std::uint8_t>(SurfaceClass::kMover));
}

TEST(CameraRobots, CamerasOnOneLinkShareTheRobotsShapes) {
  const RobotModelConstPtr robot = RobotModel::fromUrdfString(cameraJetbotText());
  CameraWorld world(nullptr);
  const CameraRobot* left = world.addRobot(*robot, "camera_link");
  EXPECT_EQ(world.addRobot(*robot, "camera_link"), left);  // a stereo pair's second camera
  const CameraRobot* other = world.addRobot(*robot, "base_link");
  EXPECT_NE(other, left);  // another link hides another housing
  EXPECT_EQ(other->numBodies(), left->numBodies());
}

TEST(CameraRobots, BodiesNoRayMeetsAreLeftOutAndTheImagesStayTheSame) {
  const RobotModelConstPtr robot = RobotModel::fromUrdfString(cameraJetbotText());
  CameraWorld world(nullptr);
  CameraEnvScene scene(world, world.addRobot(*robot, "camera_link"));
  // Eight robots on a circle of 0.5 m around a camera 5 cm up, each body at its link's rest pose.
  std::vector<RobotPose> robots(8);
  for (int k = 0; k < 8; ++k) {
    const double angle = 2.0 * M_PI * k / 8.0;
    const Eigen::Isometry3d root =
        Eigen::Translation3d(0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.03) *
        Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ());
    for (const BodyModel& body : robot->bodies()) {
      robots[k].bodies.push_back(body.parent < 0 ? root : root * body.joint_origin);
    }
  }
  CameraIntrinsics c;
  c.width = 40;
  c.height = 30;
  c.horizontal_fov = 1.5;
  c.near = 0.01;
  c.far = 10.0;
  const CameraModel m(c);
  const Eigen::Isometry3d pose = opticalFrame(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.05)));
  CameraImages all, culled;
  scene.setRobots(robots);
  scene.render(m, pose, all);
  const ViewCone view(m, pose);
  scene.setRobots(robots, true, &view);
  scene.render(m, pose, culled);
  expectSameImages(culled, all);
  EXPECT_GT(std::count(all.label.begin(), all.label.end(),
                       static_cast<std::uint8_t>(SurfaceClass::kRobot)),
            20);  // the robots ahead are in the image
}

}  // namespace
}  // namespace jetbot_rl
