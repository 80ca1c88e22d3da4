#pragma once

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/ros/deploy/depth_scan_params.h"
#include "jetbot_rl/sensors/laser_scanner.h"

namespace jetbot_rl {

/// The scan a depth image gives, as scan/source camera_depth makes it in training
/// (depthToScan()): every pixel's point between min_height and max_height above the ground
/// counts for the sample nearest its bearing from the root link, the nearest one wins.
class DepthScanConverter {
 public:
  explicit DepthScanConverter(const DepthScanParams& params) : params_(params) {}
  /// `depth`: metres (32FC1) or millimetres (16UC1, 0: none); `info`: its camera (its pixel
  /// rays kept while it stays the same); `optical` and `origin`: the camera's optical frame and
  /// the root link in a frame whose z = 0 is the ground. Returns "" or why the image is refused
  /// (its encoding, size or camera, named); `scan` is left as it was then.
  std::string convert(const sensor_msgs::Image& depth, const sensor_msgs::CameraInfo& info,
                      const Eigen::Isometry3d& optical, const Eigen::Isometry3d& origin,
                      sensor_msgs::LaserScan& scan);

 private:
  DepthScanParams params_;
  sensor_msgs::CameraInfo camera_;      // the camera the rays are of
  std::vector<Eigen::Vector3f> rays_;   // pinholeRays() of camera_
  std::vector<float> metres_, ranges_;  // scratch
};

/// jetbot_depth_scan: depth images (and their CameraInfo) in, a LaserScan per image out, the
/// camera's pose from tf at the image's time. What it cannot turn into a scan (no transform, an
/// encoding it does not read, a size its CameraInfo does not give) is counted per reason and
/// warned of (at most every 5 s).
class DepthScanPublisher {
 public:
  DepthScanPublisher(ros::NodeHandle& nh, const DepthScanParams& params);

 private:
  void onDepth(const sensor_msgs::ImageConstPtr& depth,
               const sensor_msgs::CameraInfoConstPtr& info);
  /// Counts an image refused for `why` (the key) and warns, with `detail`.
  void refuse(const std::string& why, const std::string& detail);

  DepthScanParams params_;
  DepthScanConverter converter_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  image_transport::ImageTransport transport_;
  image_transport::CameraSubscriber subscriber_;
  ros::Publisher publisher_;
  std::map<std::string, std::uint64_t> refused_;
};

/// The node's main: parameters (a bad one ends it with ROS_FATAL naming it), then spin.
int runDepthScanNode();

}  // namespace jetbot_rl
