// More than one camera on a robot: every camera of the robot description's blocks (a multicamera's
// each), with the topics and frames its ROS plugin gives; the parameters set every camera; the
// batch carries the camera camera/batch_camera names; two cameras on one topic are refused; each
// camera renders from its own place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "camera_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

const char* const kLeft = "imx219_83_stereo/left";
const char* const kRight = "imx219_83_stereo/right";

std::string urdfText(const std::string& name) {
  std::ifstream file(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/" + name);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// urdf/jetbot_stereo.urdf: the Jetbot with the IMX219-83 stereo module, loaded once.
RobotModelConstPtr stereoJetbot() {
  static const RobotModelConstPtr model =
      RobotModel::fromUrdfString(urdfText("jetbot_stereo.urdf"));
  return model;
}

/// urdf/jetbot_camera.urdf with one more camera block on base_link, published under `space`.
RobotModelConstPtr jetbotWithRearCamera(const std::string& space) {
  std::string text = urdfText("jetbot_camera.urdf");
  text.insert(text.rfind("</robot>"),
              "<gazebo reference=\"base_link\"><sensor type=\"camera\" name=\"rear\">"
              "<pose>-0.08 0 0.05 0 0 3.14159</pose><camera/>"
              "<plugin name=\"c\" filename=\"libgazebo_ros_camera.so\"><cameraName>" +
                  space + "</cameraName></plugin></sensor></gazebo>");
  return RobotModel::fromUrdfString(text);
}

TEST(Multicamera, TheStereoJetbotHasTwoCamerasAsGazeboPublishesThem) {
  const std::vector<CameraSpec> cameras = resolveCameras(CameraConfig(), *stereoJetbot(), 1.0 / 60);
  ASSERT_EQ(cameras.size(), 2u);
  const CameraSpec& left = cameras[0];
  const CameraSpec& right = cameras[1];
  EXPECT_EQ(left.name, kLeft);
  EXPECT_EQ(right.name, kRight);
  // gazebo_ros_multicamera: <cameraName>/left and /right.
  EXPECT_EQ(left.image_topic, "stereo/left/image_raw");
  EXPECT_EQ(left.info_topic, "stereo/left/camera_info");
  EXPECT_EQ(right.image_topic, "stereo/right/image_raw");
  EXPECT_EQ(right.info_topic, "stereo/right/camera_info");
  EXPECT_EQ(left.frame, "camera_link_left_optical_frame");
  EXPECT_EQ(right.frame, "camera_link_right_optical_frame");
  for (const CameraSpec& c : cameras) {
    EXPECT_EQ(c.link, "camera_link");
    EXPECT_EQ(c.intrinsics.width, 320);
    EXPECT_EQ(c.intrinsics.height, 240);
    EXPECT_DOUBLE_EQ(c.intrinsics.horizontal_fov, 1.2319);
    EXPECT_EQ(c.update_every, 2);  // 30 Hz at a 60 Hz control step
  }
  // 60 mm apart along camera_link's y axis: in the body frame and between the optical frames.
  const Eigen::Vector3d apart = left.pose_in_body.translation() - right.pose_in_body.translation();
  EXPECT_NEAR(apart.norm(), 0.06, 1e-9);
  const Eigen::Vector3d in_link =
      (left.optical_in_link.inverse() * right.optical_in_link).translation();
  EXPECT_TRUE(in_link.isApprox(Eigen::Vector3d(0.06, 0.0, 0.0), 1e-9)) << in_link.transpose();
}

TEST(Multicamera, TheParametersSetEveryCameraAndChooseTheBatchs) {
  CameraConfig c;
  c.width = 32;
  c.height = 24;
  c.batch_camera = kRight;
  const std::vector<CameraSpec> cameras = resolveCameras(c, *stereoJetbot(), 1.0 / 60);
  ASSERT_EQ(cameras.size(), 2u);
  EXPECT_EQ(cameras[0].name, kRight);  // the batch's camera first
  EXPECT_EQ(cameras[1].name, kLeft);
  for (const CameraSpec& camera : cameras) EXPECT_EQ(camera.intrinsics.width, 32);
  // camera/link picks the link's cameras; a link without a block gets one of the parameters.
  c.batch_camera.clear();
  c.link = "camera_link";
  EXPECT_EQ(resolveCameras(c, *stereoJetbot(), 1.0 / 60).size(), 2u);
  c.link = "base_link";
  const std::vector<CameraSpec> own = resolveCameras(c, *stereoJetbot(), 1.0 / 60);
  ASSERT_EQ(own.size(), 1u);
  EXPECT_EQ(own[0].name, "camera");
  // A batch camera no camera is called.
  c = CameraConfig();
  c.batch_camera = "middle";
  try {
    resolveCameras(c, *stereoJetbot(), 1.0 / 60);
    ADD_FAILURE() << "batch_camera 'middle' accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("camera/batch_camera = 'middle'"), std::string::npos) << what;
    EXPECT_NE(what.find(kLeft), std::string::npos) << what;
  }
}

TEST(Multicamera, TwoCamerasOnOneTopicAreRefusedNamingBoth) {
  // Beside the Jetbot's camera, in the robot description's order.
  const std::vector<CameraSpec> cameras =
      resolveCameras(CameraConfig(), *jetbotWithRearCamera("rear_camera"), 1.0 / 60);
  ASSERT_EQ(cameras.size(), 2u);
  EXPECT_EQ(cameras[0].name, "imx219_160");
  EXPECT_EQ(cameras[1].name, "rear");
  EXPECT_EQ(cameras[1].image_topic, "rear_camera/image_raw");
  EXPECT_EQ(cameras[1].frame, "base_link_optical_frame");
  try {
    resolveCameras(CameraConfig(), *jetbotWithRearCamera("camera"), 1.0 / 60);
    ADD_FAILURE() << "two cameras on camera/image_raw accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'imx219_160' and 'rear' would both publish camera/image_raw"),
              std::string::npos)
        << what;
  }
}

/// A batch of stereo Jetbots in the camera tests' arena, images every step without noise.
EnvConfig stereoArena(const std::string& batch_camera) {
  EnvConfig c = cameraArenaConfig(2, 1);
  c.camera.noise_std = 0.0;
  c.camera.update_every = 1;
  c.camera.batch_camera = batch_camera;
  return c;
}

/// True when `a`'s and `b`'s images are the same, bit for bit.
bool sameImages(const EnvImages& a, const EnvImages& b) {
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  return a.width == b.width && a.height == b.height &&
         std::equal(a.rgb, a.rgb + 3 * pixels, b.rgb) &&
         std::memcmp(a.depth, b.depth, pixels * sizeof(float)) == 0 &&
         std::equal(a.label, a.label + pixels, b.label);
}

TEST(Multicamera, EachCameraSeesFromItsOwnPlace) {
  BatchedEnv stereo(stereoJetbot(), stereoArena(""));
  BatchedEnv right_first(stereoJetbot(), stereoArena(kRight));
  ASSERT_EQ(stereo.numCameras(), 2);
  EXPECT_EQ(stereo.camera(0)->name, kLeft);
  EXPECT_EQ(right_first.camera(0)->name, kRight);
  EXPECT_EQ(stereo.camera(2), nullptr);
  const std::vector<float> turn{4.0f, 8.0f, 4.0f, 8.0f};
  int differ = 0;  // images in which the two cameras see differently (not a flat wall ahead)
  for (int step = 0; step < 6; ++step) {
    for (int e = 0; e < 2; ++e) {
      SCOPED_TRACE("step " + std::to_string(step) + ", env " + std::to_string(e));
      const EnvView view = stereo.view(e);
      ASSERT_TRUE(view.imaged(0) && view.imaged(1));
      // The right camera's images are the same whichever camera the batch carries.
      EXPECT_TRUE(sameImages(view.images(1), right_first.view(e).images(0)));
      EXPECT_TRUE(sameImages(view.images(0), right_first.view(e).images(1)));
      differ += sameImages(view.images(0), view.images(1)) ? 0 : 1;
      // The batch carries camera 0's.
      EXPECT_EQ(view.images(0).depth, stereo.state().images.depth.data() + e * 32 * 24);
      const Eigen::Vector3d apart =
          view.cameraPose(0).translation() - view.cameraPose(1).translation();
      EXPECT_NEAR(apart.norm(), 0.06, 1e-9);
    }
    stereo.step(turn);
    right_first.step(turn);
  }
  EXPECT_GE(differ, 6);  // 60 mm apart: only the ground and walls square ahead look the same
}

}  // namespace
}  // namespace jetbot_rl
