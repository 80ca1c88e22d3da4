#pragma once

#include <image_transport/image_transport.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/ros/env_node/state_output.h"

namespace jetbot_rl {

struct CameraSpec;
class CameraModel;

/// The CameraInfo of `spec`'s camera in frame `frame`: size, plumb_bob D = [k1, k2, p1, p2, k3],
/// K and P from Gazebo's focal length (fx = fy = width / 2 / tan(hfov / 2)), R the identity.
sensor_msgs::CameraInfo cameraInfo(const CameraSpec& spec, const std::string& frame);

/// Fills `msg` (encoding, size, step, data) with `width` x `height` rgb8 pixels converted to
/// `encoding` (rgb8, bgr8 or mono8: ITU-R BT.601 luma).
void fillColourImage(const std::uint8_t* rgb, int width, int height, const std::string& encoding,
                     sensor_msgs::Image& msg);

/**
 * The camera's images of the robot envs (docs/camera.md), through image_transport (compressed
 * transports where installed), with their CameraInfo: after each step in which an env's camera
 * made new images, under `env_<i>/` with the topic names of the camera block's ROS plugin
 * (rgb: the block's format, rgb8, bgr8 or mono8; depth: 32FC1 [m], REP 118; label: mono8),
 * stamped with simulation time, in the camera's optical frame (REP 103). An image nobody
 * subscribes to is not copied. Nothing without a camera.
 */
class CameraOutput : public StateOutput {
 public:
  /// Camera `camera`'s (BatchedEnv::camera()); topics relative to `nh` (the node's namespace);
  /// `envs` clamped to the batch.
  CameraOutput(ros::NodeHandle& nh, const BatchedEnv& env, int camera, int envs,
               const RobotNames& names, CountedSubscriberQueues& queues);
  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;

 private:
  /// One published image of every env: its publisher and info publisher per env.
  struct Stream {
    std::vector<image_transport::Publisher> images;
    std::vector<ros::Publisher> infos;
    std::vector<sensor_msgs::Image> messages;
    std::vector<std::uint8_t> filled;  // per env: its message holds the last capture's image
    sensor_msgs::CameraInfo info;      // the same for every env but its frame
  };
  /// Advertises `image_topic` (and `info_topic`, when given) of every env.
  Stream makeStream(const std::string& image_topic, const std::string& info_topic,
                    CountedSubscriberQueues& queues, const RobotNames& names);
  /// Copies env `e`'s image into `stream`'s message when anyone subscribes to it.
  template <typename Fill>
  void take(Stream& stream, int e, Fill&& fill);

  ros::NodeHandle nh_;
  int camera_;
  std::unique_ptr<image_transport::ImageTransport> transport_;
  std::vector<std::string> frames_;  // per env
  std::string colour_encoding_;
  Stream rgb_, depth_, label_;
  std::vector<std::uint8_t> due_;  // per env
  ros::Time stamp_;
};

}  // namespace jetbot_rl
