// Cameras read from a robot description's Gazebo blocks as Gazebo reads them: every field of a
// camera, depth and multicamera sensor and of its ROS plugin, SDF's defaults, TurtleBot3 Waffle's
// R200 block as ROBOTIS publishes it, the stock Jetbot's camera (urdf/jetbot_camera.urdf), and
// bad blocks named.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/robot/urdf_camera_blocks.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// A robot of one link with `gazebo` (the <gazebo> blocks' text) after it.
std::string robotWith(const std::string& gazebo) {
  return "<?xml version=\"1.0\"?><robot name=\"r\"><link name=\"base_link\"/>" + gazebo +
         "</robot>";
}

std::string cameraSensor(const std::string& type, const std::string& camera,
                         const std::string& extra = "") {
  return "<gazebo reference=\"base_link\"><sensor type=\"" + type + "\" name=\"s\">" + extra +
         camera + "</sensor></gazebo>";
}

TEST(CameraBlocks, EveryFieldReachesTheCamera) {
  const std::vector<GazeboCamera> cameras = parseCameraBlocks(robotWith(
      "<gazebo reference=\"base_link\"><sensor type=\"camera\" name=\"front\">"
      "<pose>0.1 0 0.2 0 0.3 0</pose><update_rate>15</update_rate>"
      "<camera name=\"head\"><horizontal_fov>1.2</horizontal_fov>"
      "<image><width>160</width><height>120</height><format>B8G8R8</format></image>"
      "<clip><near>0.05</near><far>50</far></clip>"
      "<noise><type>gaussian</type><mean>0.01</mean><stddev>0.02</stddev></noise>"
      "<distortion><k1>-0.1</k1><k2>0.01</k2><k3>-0.001</k3><p1>0.002</p1><p2>-0.003</p2>"
      "</distortion></camera>"
      "<plugin name=\"c\" filename=\"libgazebo_ros_camera.so\"><updateRate>10</updateRate>"
      "<cameraName>robot/cam</cameraName><imageTopicName>img</imageTopicName>"
      "<cameraInfoTopicName>info</cameraInfoTopicName><frameName>cam_optical</frameName>"
      "</plugin></sensor></gazebo>"));
  ASSERT_EQ(cameras.size(), 1u);
  const GazeboCamera& c = cameras[0];
  EXPECT_EQ(c.link, "base_link");
  EXPECT_EQ(c.sensor_name, "front");
  EXPECT_EQ(c.camera_name, "head");
  EXPECT_EQ(c.type, "camera");
  EXPECT_TRUE(c.pose.translation().isApprox(Eigen::Vector3d(0.1, 0, 0.2)));
  EXPECT_TRUE(c.pose.linear().isApprox(
      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix()));
  EXPECT_DOUBLE_EQ(c.update_rate, 15.0);
  EXPECT_DOUBLE_EQ(c.intrinsics.horizontal_fov, 1.2);
  EXPECT_EQ(c.intrinsics.width, 160);
  EXPECT_EQ(c.intrinsics.height, 120);
  EXPECT_EQ(c.format, CameraFormat::kBgr8);
  EXPECT_DOUBLE_EQ(c.intrinsics.near, 0.05);
  EXPECT_DOUBLE_EQ(c.intrinsics.far, 50.0);
  EXPECT_DOUBLE_EQ(c.noise_mean, 0.01);
  EXPECT_DOUBLE_EQ(c.noise_stddev, 0.02);
  EXPECT_DOUBLE_EQ(c.intrinsics.k1, -0.1);
  EXPECT_DOUBLE_EQ(c.intrinsics.k2, 0.01);
  EXPECT_DOUBLE_EQ(c.intrinsics.k3, -0.001);
  EXPECT_DOUBLE_EQ(c.intrinsics.p1, 0.002);
  EXPECT_DOUBLE_EQ(c.intrinsics.p2, -0.003);
  EXPECT_EQ(c.plugin, "libgazebo_ros_camera.so");
  EXPECT_DOUBLE_EQ(c.plugin_update_rate, 10.0);
  EXPECT_EQ(c.camera_topic, "robot/cam");
  EXPECT_EQ(c.image_topic, "img");
  EXPECT_EQ(c.info_topic, "info");
  EXPECT_EQ(c.frame_name, "cam_optical");
}

TEST(CameraBlocks, WhatABlockLeavesOutIsSdfsDefault) {
  const std::vector<GazeboCamera> cameras =
      parseCameraBlocks(robotWith(cameraSensor("camera", "<camera/>")));
  ASSERT_EQ(cameras.size(), 1u);
  const CameraIntrinsics& c = cameras[0].intrinsics;
  EXPECT_EQ(c.width, 320);
  EXPECT_EQ(c.height, 240);
  EXPECT_DOUBLE_EQ(c.horizontal_fov, 1.047);
  EXPECT_DOUBLE_EQ(c.near, 0.1);
  EXPECT_DOUBLE_EQ(c.far, 100.0);
  EXPECT_EQ(cameras[0].format, CameraFormat::kRgb8);
  EXPECT_EQ(cameras[0].plugin, "");
  EXPECT_DOUBLE_EQ(cameras[0].noise_stddev, 0.0);
  // A ray sensor or another robot's blocks are no camera.
  EXPECT_TRUE(parseCameraBlocks(robotWith(cameraSensor("ray", "<ray/>"))).empty());
}

TEST(CameraBlocks, TurtleBot3WaffleR200AsRobotisPublishesIt) {
  // turtlebot3_description/urdf/turtlebot3_waffle.gazebo.xacro (noetic), $(arg camera_visual)
  // expanded to false.
  const std::vector<GazeboCamera> cameras = parseCameraBlocks(robotWith(R"(
  <gazebo reference="camera_rgb_frame">
    <sensor type="depth" name="realsense_R200">
      <always_on>true</always_on>
      <visualize>false</visualize>
      <camera>
          <horizontal_fov>1.3439</horizontal_fov>
          <image>
              <width>1920</width>
              <height>1080</height>
              <format>R8G8B8</format>
          </image>
          <depth_camera></depth_camera>
          <clip>
              <near>0.03</near>
              <far>100</far>
          </clip>
      </camera>
      <plugin name="camera_controller" filename="libgazebo_ros_openni_kinect.so">
        <baseline>0.2</baseline>
        <alwaysOn>true</alwaysOn>
        <updateRate>30.0</updateRate>
        <cameraName>camera</cameraName>
        <frameName>camera_rgb_optical_frame</frameName>
        <imageTopicName>rgb/image_raw</imageTopicName>
        <depthImageTopicName>depth/image_raw</depthImageTopicName>
        <pointCloudTopicName>depth/points</pointCloudTopicName>
        <cameraInfoTopicName>rgb/camera_info</cameraInfoTopicName>
        <depthImageCameraInfoTopicName>depth/camera_info</depthImageCameraInfoTopicName>
        <pointCloudCutoff>0.4</pointCloudCutoff>
        <hackBaseline>0.07</hackBaseline>
        <distortionK1>0.0</distortionK1>
        <distortionK2>0.0</distortionK2>
        <distortionK3>0.0</distortionK3>
        <distortionT1>0.0</distortionT1>
        <distortionT2>0.0</distortionT2>
        <CxPrime>0.0</CxPrime>
        <Cx>0.0</Cx>
        <Cy>0.0</Cy>
        <focalLength>0</focalLength>
      </plugin>
    </sensor>
  </gazebo>)"));
  ASSERT_EQ(cameras.size(), 1u);
  const GazeboCamera& c = cameras[0];
  EXPECT_EQ(c.link, "camera_rgb_frame");
  EXPECT_EQ(c.type, "depth");
  EXPECT_EQ(c.intrinsics.width, 1920);
  EXPECT_EQ(c.intrinsics.height, 1080);
  EXPECT_DOUBLE_EQ(c.intrinsics.horizontal_fov, 1.3439);
  EXPECT_DOUBLE_EQ(c.intrinsics.near, 0.03);
  EXPECT_DOUBLE_EQ(c.plugin_update_rate, 30.0);
  EXPECT_EQ(c.camera_topic, "camera");
  EXPECT_EQ(c.image_topic, "rgb/image_raw");
  EXPECT_EQ(c.info_topic, "rgb/camera_info");
  EXPECT_EQ(c.depth_image_topic, "depth/image_raw");
  EXPECT_EQ(c.depth_info_topic, "depth/camera_info");
  EXPECT_EQ(c.frame_name, "camera_rgb_optical_frame");
  // CameraInfo's focal length from the fov, as the plugin computes it: w/2 / tan(hfov/2).
  EXPECT_NEAR(CameraModel(c.intrinsics).fx(), 960.0 / std::tan(1.3439 / 2.0), 1e-9);
}

TEST(CameraBlocks, AMulticameraGivesEachCameraItsPose) {
  const std::vector<GazeboCamera> cameras = parseCameraBlocks(robotWith(cameraSensor(
      "multicamera",
      "<camera name=\"left\"><pose>0 0.07 0 0 0 0</pose></camera>"
      "<camera name=\"right\"><pose>0 -0.07 0 0 0 0</pose><image><width>64</width></image>"
      "</camera>",
      "<pose>0.2 0 0.1 0 0 0</pose>")));
  ASSERT_EQ(cameras.size(), 2u);
  EXPECT_EQ(cameras[0].camera_name, "left");
  EXPECT_EQ(cameras[1].camera_name, "right");
  EXPECT_TRUE(cameras[0].pose.translation().isApprox(Eigen::Vector3d(0.2, 0.07, 0.1)));
  EXPECT_TRUE(cameras[1].pose.translation().isApprox(Eigen::Vector3d(0.2, -0.07, 0.1)));
  EXPECT_EQ(cameras[0].intrinsics.width, 320);
  EXPECT_EQ(cameras[1].intrinsics.width, 64);
}

TEST(CameraBlocks, BadBlocksAreNamed) {
  const auto refused = [](const std::string& camera, const std::string& expected) {
    try {
      parseCameraBlocks(robotWith(cameraSensor("camera", camera)));
      ADD_FAILURE() << camera << " accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("camera sensor 's' on link 'base_link'"), std::string::npos) << what;
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  };
  refused("<camera><image><width>0</width></image></camera>", "width = 0");
  refused("<camera><image><height>-5</height></image></camera>", "height = -5");
  refused("<camera><image><width>5000</width></image></camera>", "width = 5000");
  refused("<camera><horizontal_fov>0</horizontal_fov></camera>", "horizontal_fov = 0");
  refused("<camera><horizontal_fov>3.2</horizontal_fov></camera>", "horizontal_fov = 3.2");
  refused("<camera><clip><near>2</near><far>1</far></clip></camera>", "clip/far = 1");
  refused("<camera><image><format>BAYER_RGGB8</format></image></camera>", "<format> 'BAYER_RGGB8'");
  refused("<camera><horizontal_fov>wide</horizontal_fov></camera>", "<horizontal_fov> 'wide'");
  refused("", "no <camera> element");
}

TEST(CameraBlocks, TheStockJetbotsCamera) {
  const std::string path = std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf";
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  const std::vector<GazeboCamera> cameras = parseCameraBlocks(text.str());
  ASSERT_EQ(cameras.size(), 1u);
  const GazeboCamera& c = cameras[0];
  EXPECT_EQ(c.link, "camera_link");
  EXPECT_EQ(c.intrinsics.width, 224);
  EXPECT_EQ(c.intrinsics.height, 224);
  EXPECT_EQ(c.frame_name, "camera_optical_frame");
  EXPECT_EQ(c.image_topic, "image_raw");
  // About 160 degrees across the diagonal, as the IMX219-160 module.
  const CameraModel model(c.intrinsics);
  const double half_diagonal_px = std::hypot(model.cx() + 0.5, model.cy() + 0.5);
  EXPECT_NEAR(2.0 * std::atan(half_diagonal_px / model.fx()) * 180.0 / M_PI, 160.0, 1.0);
  // The robot drives as the stock Jetbot: the camera adds no body.
  const RobotModelConstPtr robot = RobotModel::fromUrdfFile(path);
  EXPECT_EQ(robot->bodies().size(), test::jetbot()->bodies().size());
}

}  // namespace
}  // namespace jetbot_rl
