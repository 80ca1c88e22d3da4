#include "jetbot_rl/ros/deploy/image_input.h"

#include <image_transport/exception.h>
#include <ros/console.h>
#include <sensor_msgs/image_encodings.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

namespace enc = sensor_msgs::image_encodings;

/// OpenCV's conversion of `encoding` to rgb (-1: none needed), or false for one not taken.
bool conversionOf(const std::string& encoding, int& channels, int& code) {
  if (encoding == enc::RGB8) {
    channels = 3, code = -1;
  } else if (encoding == enc::BGR8) {
    channels = 3, code = cv::COLOR_BGR2RGB;
  } else if (encoding == enc::RGBA8) {
    channels = 4, code = cv::COLOR_RGBA2RGB;
  } else if (encoding == enc::BGRA8) {
    channels = 4, code = cv::COLOR_BGRA2RGB;
  } else if (encoding == enc::MONO8) {
    channels = 1, code = cv::COLOR_GRAY2RGB;
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::string policyImage(const sensor_msgs::Image& msg, int width, int height,
                        std::vector<std::uint8_t>& rgb) {
  int channels = 0, code = -1;
  if (!conversionOf(msg.encoding, channels, code)) {
    return "with encoding '" + msg.encoding +
           "': the policy takes rgb8, bgr8, rgba8, bgra8 or mono8";
  }
  if (msg.width == 0 || msg.height == 0) {
    return "of width " + std::to_string(msg.width) + " x height " + std::to_string(msg.height);
  }
  const std::uint64_t row = static_cast<std::uint64_t>(msg.width) * channels;
  if (msg.step < row) {
    return "with step " + std::to_string(msg.step) + " < width " + std::to_string(msg.width) +
           " x " + std::to_string(channels) + " bytes (" + msg.encoding + ")";
  }
  if (msg.data.size() != static_cast<std::uint64_t>(msg.step) * msg.height) {
    return "with " + std::to_string(msg.data.size()) + " bytes of data, not step " +
           std::to_string(msg.step) + " x height " + std::to_string(msg.height);
  }
  // OpenCV reads the message's bytes in place (it writes only into its own results).
  const cv::Mat source(static_cast<int>(msg.height), static_cast<int>(msg.width), CV_8UC(channels),
                       const_cast<std::uint8_t*>(msg.data.data()), msg.step);
  cv::Mat resized;
  if (source.cols == width && source.rows == height) {
    resized = source;
  } else {
    cv::resize(source, resized, cv::Size(width, height), 0.0, 0.0, cv::INTER_AREA);
  }
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * height * 3);
  cv::Mat result(height, width, CV_8UC3, out.data());
  if (code < 0) {
    resized.copyTo(result);
  } else {
    cv::cvtColor(resized, result, code);
  }
  rgb.swap(out);
  return "";
}

ImageInput::ImageInput(ros::NodeHandle& nh, const std::string& topic, const std::string& transport,
                       int width, int height, double timeout, DropCounter& drops)
    : width_(width), height_(height), transport_name_(transport), transport_(nh) {
  const image_transport::TransportHints hints(transport, ros::TransportHints().tcpNoDelay());
  const auto subscribe = [&](FreshInput<sensor_msgs::Image>::Callback callback) {
    try {
      auto sub = std::make_shared<image_transport::Subscriber>(transport_.subscribe(
          topic, 2, boost::function<void(const sensor_msgs::ImageConstPtr&)>(callback),
          ros::VoidPtr(), hints));
      return FreshInput<sensor_msgs::Image>::Subscription{sub, [sub] { return sub->getTopic(); }};
    } catch (const image_transport::TransportLoadException& e) {
      throw ConfigError("image_transport: '" + transport_name_ +
                        "' cannot be loaded (its plugin is not installed?): " + e.what());
    }
  };
  const auto check = [this](const sensor_msgs::Image& msg) {
    std::string why = policyImage(msg, width_, height_, rgb_);
    if (!why.empty()) return "refused: an image " + why;
    // A camera of another shape is squeezed into the trained one: it sees the world distorted.
    const double aspect = static_cast<double>(msg.width) / msg.height;
    const double trained = static_cast<double>(width_) / height_;
    if (!warned_aspect_ && std::abs(aspect / trained - 1.0) > 0.01) {
      warned_aspect_ = true;
      ROS_WARN("images on %s are %u x %u, the policy's %d x %d: squeezed to its aspect ratio",
               this->topic().c_str(), msg.width, msg.height, width_, height_);
    }
    return std::string();
  };
  input_ =
      std::make_unique<FreshInput<sensor_msgs::Image>>(subscribe, "image", timeout, check, drops);
}

std::string ImageInput::describe() const {
  return std::to_string(width_) + " x " + std::to_string(height_) + " rgb8 images from " + topic() +
         " (" + transport_name_ + " transport)";
}

}  // namespace jetbot_rl
