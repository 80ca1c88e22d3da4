#pragma once

// What a robot description's <gazebo> blocks say about the robot, read as Gazebo (classic) reads
// them: a planar ray sensor (<gazebo reference="LINK"><sensor type="ray">), the cameras
// (urdf_camera_blocks.h) and the differential drive plugin (libgazebo_ros_diff_drive.so). Their
// values are the defaults of the scanner's, the camera's and the drive's parameters; a parameter
// that is set wins (docs/world.md, docs/camera.md).

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/robot/urdf_camera_blocks.h"

namespace jetbot_rl {

/// A <sensor type="ray"> block, with SDF's defaults for the elements it leaves out.
struct GazeboRaySensor {
  std::string link;  ///< The block's reference link.
  std::string name;  ///< The sensor's name attribute.
  /// <pose> of the sensor in the link frame (x y z roll pitch yaw).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double update_rate = 0.0;   ///< <update_rate> [Hz]; 0: every simulation step.
  int samples = 640;          ///< <ray><scan><horizontal><samples>.
  double min_angle = 0.0;     ///< <min_angle> [rad].
  double max_angle = 0.0;     ///< <max_angle> [rad].
  double range_min = 0.0;     ///< <ray><range><min> [m].
  double range_max = 0.0;     ///< <ray><range><max> [m].
  double noise_mean = 0.0;    ///< <ray><noise><mean> [m] (type gaussian).
  double noise_stddev = 0.0;  ///< <ray><noise><stddev> [m] (type gaussian).
};

/// A libgazebo_ros_diff_drive.so plugin block (ROS 1 names, or ROS 2's where ROS 1's are absent);
/// 0 or empty: the block does not give it.
struct GazeboDiffDrive {
  std::string left_joint, right_joint;  ///< <leftJoint>, <rightJoint>.
  double wheel_separation = 0.0;        ///< <wheelSeparation> [m].
  double wheel_diameter = 0.0;          ///< <wheelDiameter> [m].
  double wheel_torque = 0.0;            ///< <wheelTorque> [N m].
};

/// The <gazebo> blocks of a robot description that jetbot_rl reads.
struct GazeboBlocks {
  std::optional<GazeboRaySensor> ray;         ///< The first ray sensor, if any.
  std::optional<GazeboDiffDrive> diff_drive;  ///< The first diff drive plugin, if any.
  std::vector<GazeboCamera> cameras;          ///< Every camera, in the order they appear.
};

/// Reads the <gazebo> blocks of URDF text (the rest of the file is urdfdom's). Throws ModelError
/// naming the sensor or plugin and the element whose value is not a number or is malformed (a
/// camera's values: parseCameraBlocks()).
GazeboBlocks parseGazeboBlocks(const std::string& urdf_xml);

}  // namespace jetbot_rl
