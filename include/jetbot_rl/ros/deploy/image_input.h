#pragma once

#include <image_transport/image_transport.h>
#include <ros/node_handle.h>
#include <sensor_msgs/Image.h>

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/ros/common/drop_counter.h"
#include "jetbot_rl/ros/deploy/fresh_input.h"

namespace jetbot_rl {

/// Converts a robot's camera image `msg` to what an image policy takes: `width` x `height` [px]
/// rgb8, row-major from the top left pixel, into `rgb`. The image is resized by area averaging
/// (OpenCV's INTER_AREA: a pixel is the mean of the camera pixels it covers) and its encoding
/// converted (rgb8, bgr8, rgba8, bgra8, mono8). Returns "" when converted, else why not, naming
/// the field and its value (an encoding it cannot take, a size or step its data do not match);
/// `rgb` is then unchanged.
std::string policyImage(const sensor_msgs::Image& msg, int width, int height,
                        std::vector<std::uint8_t>& rgb);

/**
 * The robot's camera as an image policy's input (the deploy node): sensor_msgs/Image through
 * image_transport (raw, or compressed where its plugin is installed), each image converted to the
 * policy's size and rgb8 on arrival (policyImage()); images it cannot convert are dropped and
 * counted, as odometry is. An image older than the timeout is stale.
 */
class ImageInput {
 public:
  /// `width` x `height` [px]: the policy's. Throws ConfigError naming image_transport when
  /// `transport`'s plugin cannot be loaded.
  ImageInput(ros::NodeHandle& nh, const std::string& topic, const std::string& transport, int width,
             int height, double timeout, DropCounter& drops);

  /// True when an image came within the timeout.
  bool fresh() const { return input_->fresh(); }
  /// Seconds since the newest image (infinity before one came) [s, wall].
  double age() const { return input_->age(); }
  std::string topic() const { return input_->topic(); }
  /// The newest image taken, as the policy takes it: height x width x 3 bytes, rgb8.
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }
  /// "W x H rgb8 from <topic> (<transport>)", for the start-up line.
  std::string describe() const;

 private:
  int width_, height_;
  std::string transport_name_;
  image_transport::ImageTransport transport_;
  std::vector<std::uint8_t> rgb_;
  bool warned_aspect_ = false;
  std::unique_ptr<FreshInput<sensor_msgs::Image>> input_;
};

}  // namespace jetbot_rl
