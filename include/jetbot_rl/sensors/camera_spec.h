#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/robot/urdf_camera_blocks.h"
#include "jetbot_rl/sensors/camera_config.h"
#include "jetbot_rl/sensors/camera_model.h"

namespace jetbot_rl {

/// A camera in use: CameraConfig resolved against the robot description's Gazebo camera block.
struct CameraSpec {
  /// The block's sensor name (a multicamera's camera: SENSOR/CAMERA); "camera" when declared by
  /// parameters alone.
  std::string name;
  std::string link;  ///< URDF link the camera sits on.
  int body = 0;      ///< The robot body the link belongs to.
  /// The camera's body frame (x forward, y left, z up) in the body's link frame: the link's
  /// offset, the sensor's <pose> and the <camera>'s; its optical frame is opticalFrame() of it.
  Eigen::Isometry3d pose_in_body = Eigen::Isometry3d::Identity();
  /// Its optical frame (z forward, x right, y down) in the link's frame: the `frame` tf gets when
  /// it is no link of the robot description.
  Eigen::Isometry3d optical_in_link = Eigen::Isometry3d::Identity();
  CameraIntrinsics intrinsics;
  bool rgb = true, depth = false, label = false;  ///< The images made.
  CameraFormat format = CameraFormat::kRgb8;      ///< The rgb image's encoding when published.
  double noise_mean = 0.0, noise_std = 0.0;       ///< On [0, 1] intensities.
  int update_every = 1;                           ///< [control steps]
  std::string sensor_name;  ///< The block's sensor (empty: declared by parameters).
  bool shadows = false;     ///< The directional light casts shadows (camera/shadows).
  /// Appearance randomisation (camera/random_colours, ...; CameraConfig's fields).
  bool random_colours = false, random_light_direction = false;
  std::vector<double> light_intensity, exposure, pose_jitter;  ///< [] when off.
  /// True when anything of the appearance is drawn at a reset.
  bool randomizesAppearance() const {
    return random_colours || random_light_direction || !light_intensity.empty() ||
           !exposure.empty() || !pose_jitter.empty();
  }
  // Topic names relative to the robot's namespace and the optical frame, as the block's ROS
  // plugin gives them (gazebo_ros_camera, gazebo_ros_openni_kinect), else those plugins' defaults.
  std::string image_topic;        ///< e.g. camera/image_raw, camera/rgb/image_raw
  std::string info_topic;         ///< e.g. camera/camera_info
  std::string depth_image_topic;  ///< e.g. camera/depth/image_raw
  std::string depth_info_topic;   ///< e.g. camera/depth/camera_info
  std::string label_topic;        ///< camera namespace + label/image_raw
  std::string frame;              ///< The plugin's <frameName>, else LINK_optical_frame.
  /// Per value, where it came from: "camera/<name>", "Gazebo" or "default".
  std::string link_from, size_from, fov_from, clip_from, distortion_from, images_from, noise_from,
      update_from;
};

/// The cameras `config` gives on `robot`, whose control step is `control_dt` [s]: one per camera
/// of the robot description's Gazebo blocks (those on camera/link when it is set; a multicamera
/// gives one per <camera>), or one of the parameters alone on camera/link when it has no block;
/// none when disabled. The camera camera/batch_camera names comes first, else the description's
/// order. Throws ConfigError naming the field (camera/link not in the URDF, a size, fov, clip or
/// distortion no camera has, a batch_camera no camera has) and its value, and the block the value
/// came from when that is what is wrong; two cameras that would publish on one topic, naming both.
std::vector<CameraSpec> resolveCameras(const CameraConfig& config, const RobotModel& robot,
                                       double control_dt);

/// One line for the start-up echo: link, size, fov, clip, images, noise, update, and sources.
std::string describeCamera(const CameraSpec& spec);

}  // namespace jetbot_rl
