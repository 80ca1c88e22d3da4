#pragma once

// The cameras a robot description declares as Gazebo (classic) reads them: <gazebo
// reference="LINK"> blocks holding a <sensor type="camera">, "depth" or "multicamera" (one camera
// per <camera> of a multicamera), with the ROS plugin that publishes it (libgazebo_ros_camera.so,
// libgazebo_ros_openni_kinect.so, libgazebo_ros_depth_camera.so, libgazebo_ros_multicamera.so).
// Their values become a camera's defaults; parameters win (issue 46, in progress).

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "jetbot_rl/sensors/camera_model.h"

namespace jetbot_rl {

/// The image formats a camera block may give (SDF's <image><format>).
enum class CameraFormat { kRgb8, kBgr8, kMono8 };

/// One camera of a <sensor> block, with SDF's defaults for what the block leaves out.
struct GazeboCamera {
  std::string link;         ///< The block's reference link.
  std::string sensor_name;  ///< The sensor's name attribute.
  std::string camera_name;  ///< The <camera name="..."> (multicamera: each camera's).
  std::string type;         ///< "camera", "depth" or "multicamera".
  /// The camera's body frame (x forward, y left, z up) in the link frame: the sensor's <pose>,
  /// then the <camera>'s.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double update_rate = 0.0;     ///< The sensor's <update_rate> [Hz]; 0: every simulation step.
  CameraIntrinsics intrinsics;  ///< <horizontal_fov>, <image>, <clip>, <distortion>.
  CameraFormat format = CameraFormat::kRgb8;  ///< <image><format> (R8G8B8, B8G8R8 or L8)
  double noise_mean = 0.0;    ///< <noise> (type gaussian): per channel, on [0, 1] intensities.
  double noise_stddev = 0.0;  ///< <noise><stddev>.
  // The ROS plugin's elements (empty or 0 when there is none or it leaves one out).
  std::string plugin;             ///< Its filename, e.g. libgazebo_ros_openni_kinect.so.
  std::string camera_topic;       ///< <cameraName>: the namespace of its topics.
  std::string image_topic;        ///< <imageTopicName>.
  std::string info_topic;         ///< <cameraInfoTopicName>.
  std::string depth_image_topic;  ///< <depthImageTopicName> (depth plugins).
  std::string depth_info_topic;   ///< <depthImageCameraInfoTopicName> or <depthImageInfoTopicName>.
  std::string frame_name;         ///< <frameName>.
  double plugin_update_rate = 0.0;  ///< <updateRate> [Hz]; 0: the sensor's.
};

/// The cameras of URDF text's <gazebo> blocks, in the order they appear. Throws ModelError
/// naming the sensor, its link and the element whose value is not a number, an unknown
/// <format>, and (ConfigError, validateIntrinsics()) a value no camera has: a size outside
/// [1, 4096], a field of view outside (0, pi), near <= 0 or >= far, a folding distortion.
std::vector<GazeboCamera> parseCameraBlocks(const std::string& urdf_xml);

}  // namespace jetbot_rl
