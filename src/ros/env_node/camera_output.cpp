#include "jetbot_rl/ros/env_node/camera_output.h"

#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "jetbot_rl/sensors/camera_spec.h"

namespace jetbot_rl {
namespace {

// Images per subscriber connection: a viewer that falls behind gets the newest.
constexpr std::size_t kImageQueue = 2;

const std::string& colourEncoding(CameraFormat format) {
  switch (format) {
    case CameraFormat::kBgr8:
      return sensor_msgs::image_encodings::BGR8;
    case CameraFormat::kMono8:
      return sensor_msgs::image_encodings::MONO8;
    case CameraFormat::kRgb8:
      break;
  }
  return sensor_msgs::image_encodings::RGB8;
}

/// Sets `msg`'s size fields for `width` x `height` pixels of `bytes` bytes each.
void shape(int width, int height, int bytes, const std::string& encoding, sensor_msgs::Image& msg) {
  msg.width = static_cast<std::uint32_t>(width);
  msg.height = static_cast<std::uint32_t>(height);
  msg.encoding = encoding;
  msg.is_bigendian = 0;
  msg.step = static_cast<std::uint32_t>(width * bytes);
  msg.data.resize(static_cast<std::size_t>(msg.step) * height);
}

}  // namespace

sensor_msgs::CameraInfo cameraInfo(const CameraSpec& spec, const std::string& frame) {
  const CameraModel model(spec.intrinsics);
  const CameraIntrinsics& c = spec.intrinsics;
  sensor_msgs::CameraInfo info;
  info.header.frame_id = frame;
  info.width = static_cast<std::uint32_t>(c.width);
  info.height = static_cast<std::uint32_t>(c.height);
  info.distortion_model = "plumb_bob";
  info.D = {c.k1, c.k2, c.p1, c.p2, c.k3};
  info.K = {model.fx(), 0.0, model.cx(), 0.0, model.fy(), model.cy(), 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {model.fx(), 0.0, model.cx(), 0.0, 0.0, model.fy(), model.cy(), 0.0, 0.0, 0.0, 1.0, 0.0};
  return info;
}

void fillColourImage(const std::uint8_t* rgb, int width, int height, const std::string& encoding,
                     sensor_msgs::Image& msg) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  if (encoding == sensor_msgs::image_encodings::MONO8) {
    shape(width, height, 1, encoding, msg);
    for (std::size_t i = 0; i < pixels; ++i) {
      const std::uint8_t* p = rgb + 3 * i;
      msg.data[i] =
          static_cast<std::uint8_t>(std::lround(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]));
    }
    return;
  }
  shape(width, height, 3, encoding, msg);
  if (encoding == sensor_msgs::image_encodings::RGB8) {
    std::memcpy(msg.data.data(), rgb, 3 * pixels);
    return;
  }
  for (std::size_t i = 0; i < pixels; ++i) {  // bgr8
    for (int c = 0; c < 3; ++c) msg.data[3 * i + c] = rgb[3 * i + 2 - c];
  }
}

CameraOutput::Stream CameraOutput::makeStream(const std::string& image_topic,
                                              const std::string& info_topic,
                                              CountedSubscriberQueues& queues,
                                              const RobotNames& names) {
  Stream stream;
  for (std::size_t e = 0; e < frames_.size(); ++e) {
    const int env = static_cast<int>(e);
    // Queue 0 for every transport the plugins offer; each connection keeps 2 images, counted.
    stream.images.push_back(transport_->advertise(names.topic(env, image_topic), 0));
    if (queues.addWithSubtopics(stream.images.back().getTopic(), kImageQueue).empty()) {
      warnUncounted(stream.images.back().getTopic());
    }
    if (!info_topic.empty()) {
      stream.infos.push_back(advertiseCounted<sensor_msgs::CameraInfo>(
          nh_, names.topic(env, info_topic), kImageQueue, queues));
    }
    stream.messages.emplace_back();
    stream.messages.back().header.frame_id = frames_[e];
  }
  stream.filled.assign(frames_.size(), 0);
  return stream;
}

CameraOutput::CameraOutput(ros::NodeHandle& nh, const BatchedEnv& env, int camera, int envs,
                           const RobotNames& names, CountedSubscriberQueues& queues)
    : nh_(nh), camera_(camera) {
  const CameraSpec* spec = env.camera(camera);
  if (!spec) return;
  const int n = std::clamp(envs, 0, env.numEnvs());
  for (int e = 0; e < n; ++e) frames_.push_back(names.frame(e, spec->frame));
  transport_ = std::make_unique<image_transport::ImageTransport>(nh_);
  colour_encoding_ = colourEncoding(spec->format);
  const sensor_msgs::CameraInfo info = cameraInfo(*spec, "");
  if (spec->rgb) rgb_ = makeStream(spec->image_topic, spec->info_topic, queues, names);
  if (spec->depth) {
    depth_ = makeStream(spec->depth_image_topic, spec->depth_info_topic, queues, names);
  }
  if (spec->label) label_ = makeStream(spec->label_topic, "", queues, names);
  for (Stream* stream : {&rgb_, &depth_, &label_}) stream->info = info;
  due_.assign(n, 0);
}

template <typename Fill>
void CameraOutput::take(Stream& stream, int e, Fill&& fill) {
  if (stream.images.empty() || stream.images[e].getNumSubscribers() == 0) return;
  fill(stream.messages[e]);
  stream.filled[e] = 1;
}

void CameraOutput::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool) {
  for (std::size_t i = 0; i < due_.size(); ++i) {
    const int e = static_cast<int>(i);
    const EnvView view = env.view(e);
    if (!view.imaged(camera_)) continue;
    const EnvImages images = view.images(camera_);
    take(rgb_, e, [&](sensor_msgs::Image& m) {
      fillColourImage(images.rgb, images.width, images.height, colour_encoding_, m);
    });
    take(depth_, e, [&](sensor_msgs::Image& m) {
      shape(images.width, images.height, 4, sensor_msgs::image_encodings::TYPE_32FC1, m);
      std::memcpy(m.data.data(), images.depth, m.data.size());
    });
    take(label_, e, [&](sensor_msgs::Image& m) {
      shape(images.width, images.height, 1, sensor_msgs::image_encodings::MONO8, m);
      std::memcpy(m.data.data(), images.label, m.data.size());
    });
    due_[i] = 1;
  }
  stamp_ = msg->header.stamp;
}

void CameraOutput::send() {
  for (std::size_t e = 0; e < due_.size(); ++e) {
    if (!due_[e]) continue;
    due_[e] = 0;
    for (Stream* stream : {&rgb_, &depth_, &label_}) {
      if (stream->images.empty()) continue;
      if (stream->filled[e]) {
        stream->filled[e] = 0;
        stream->messages[e].header.stamp = stamp_;
        stream->images[e].publish(stream->messages[e]);
      }
      if (!stream->infos.empty()) {
        stream->info.header.stamp = stamp_;
        stream->info.header.frame_id = frames_[e];
        stream->infos[e].publish(stream->info);
      }
    }
  }
}

}  // namespace jetbot_rl
