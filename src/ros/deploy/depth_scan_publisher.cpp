// jetbot_depth_scan: a robot's depth camera turned into the scan training made of the simulated
// camera's depth (depth_scan_publisher.h).
#include "jetbot_rl/ros/deploy/depth_scan_publisher.h"

#include <sensor_msgs/image_encodings.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/checkpoint_meta.h"
#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/sensors/depth_scan.h"

namespace jetbot_rl {
namespace {

bool sameCamera(const sensor_msgs::CameraInfo& a, const sensor_msgs::CameraInfo& b) {
  return a.width == b.width && a.height == b.height && a.K == b.K && a.D == b.D &&
         a.distortion_model == b.distortion_model;
}

}  // namespace

void checkFieldRules(const DepthScanParams& p) {
  if (!p.angles.empty() && !(p.angles.size() == 2 && std::isfinite(p.angles[0]) &&
                             std::isfinite(p.angles[1]) && p.angles[0] < p.angles[1])) {
    throwInvalid("angles", listText(p.angles), "must be [] or [min, max] with min < max [rad]");
  }
  if (!(p.range[0] < p.range[1])) {
    throwInvalid("range", listText(p.range), "must be [min, max] with min < max [m]");
  }
  if (!(p.min_height < p.max_height)) {
    std::ostringstream rule;
    rule << "must be below max_height " << p.max_height;
    throwInvalid("min_height", p.min_height, rule.str());
  }
}

std::string DepthScanConverter::convert(const sensor_msgs::Image& depth,
                                        const sensor_msgs::CameraInfo& info,
                                        const Eigen::Isometry3d& optical,
                                        const Eigen::Isometry3d& origin,
                                        sensor_msgs::LaserScan& scan) {
  namespace enc = sensor_msgs::image_encodings;
  const bool metres = depth.encoding == enc::TYPE_32FC1;
  if (!metres && depth.encoding != enc::TYPE_16UC1) {
    return "encoding '" + depth.encoding + "' (a depth image is 32FC1 or 16UC1)";
  }
  if (depth.width != info.width || depth.height != info.height || depth.width == 0 ||
      depth.height == 0) {
    return "size " + std::to_string(depth.width) + " x " + std::to_string(depth.height) +
           " (its CameraInfo says " + std::to_string(info.width) + " x " +
           std::to_string(info.height) + ")";
  }
  const std::size_t bytes = metres ? 4 : 2;
  if (depth.step < depth.width * bytes ||
      depth.data.size() < static_cast<std::size_t>(depth.step) * depth.height) {
    return "step " + std::to_string(depth.step) + " and " + std::to_string(depth.data.size()) +
           " bytes for " + std::to_string(depth.width) + " x " + std::to_string(depth.height) +
           " " + depth.encoding;
  }
  if (depth.is_bigendian) return "is_bigendian 1 (this machine's order is little-endian)";
  if (rays_.empty() || !sameCamera(camera_, info)) {
    if (!info.distortion_model.empty() && info.distortion_model != "plumb_bob" &&
        info.distortion_model != "rational_polynomial") {
      return "CameraInfo distortion_model '" + info.distortion_model + "' (plumb_bob or none)";
    }
    try {
      std::vector<double> d(info.D.begin(), info.D.end());
      if (d.size() > 5) {  // rational_polynomial's first five are plumb_bob's; the rest must be 0
        for (std::size_t i = 5; i < d.size(); ++i) {
          if (d[i] != 0.0) return "CameraInfo D with k4-k6 (plumb_bob's five only)";
        }
        d.resize(5);
      }
      rays_ = pinholeRays(static_cast<int>(info.width), static_cast<int>(info.height), info.K[0],
                          info.K[4], info.K[2], info.K[5], d);
    } catch (const Error& e) {
      rays_.clear();
      return std::string("CameraInfo: ") + e.what();
    }
    camera_ = info;
  }
  const std::size_t w = depth.width, h = depth.height;
  metres_.resize(w * h);
  for (std::size_t v = 0; v < h; ++v) {
    const std::uint8_t* row = depth.data.data() + v * depth.step;
    for (std::size_t u = 0; u < w; ++u) {
      if (metres) {
        std::memcpy(&metres_[v * w + u], row + 4 * u, 4);
      } else {
        std::uint16_t mm;
        std::memcpy(&mm, row + 2 * u, 2);
        metres_[v * w + u] = mm == 0 ? std::numeric_limits<float>::quiet_NaN() : mm * 0.001f;
      }
    }
  }
  ScannerSpec spec;
  spec.source = ScanSource::kCameraDepth;
  spec.samples = params_.samples > 0 ? params_.samples : static_cast<int>(w);
  const double half = std::atan(w / 2.0 / info.K[0]);  // training's default: +- hfov / 2
  spec.min_angle = params_.angles.size() == 2 ? params_.angles[0] : -half;
  spec.max_angle = params_.angles.size() == 2 ? params_.angles[1] : half;
  spec.range_min = params_.range[0];
  spec.range_max = params_.range[1];
  spec.min_height = params_.min_height;
  spec.max_height = params_.max_height;
  ranges_.resize(static_cast<std::size_t>(spec.samples));
  depthToScan(spec, rays_, metres_.data(), optical, origin, ranges_.data());
  scan.header.stamp = depth.header.stamp;
  scan.angle_min = static_cast<float>(spec.min_angle);
  scan.angle_max = static_cast<float>(spec.max_angle);
  scan.angle_increment = static_cast<float>(spec.angleIncrement());
  scan.time_increment = 0.0f;
  scan.scan_time = 0.0f;
  scan.range_min = static_cast<float>(spec.range_min);
  scan.range_max = static_cast<float>(spec.range_max);
  scan.ranges = ranges_;
  scan.intensities.clear();
  return "";
}

DepthScanPublisher::DepthScanPublisher(ros::NodeHandle& nh, const DepthScanParams& params)
    : params_(params),
      converter_(params),
      listener_(tf_),
      transport_(nh),
      publisher_(nh.advertise<sensor_msgs::LaserScan>(params.scan_topic, 10)) {
  subscriber_ =
      transport_.subscribeCamera(params_.depth_topic, 2, &DepthScanPublisher::onDepth, this,
                                 image_transport::TransportHints(params_.image_transport));
  ROS_INFO(
      "jetbot_depth_scan: depth images on %s (%s) -> LaserScan on %s in %s, heights [%g, %g] m "
      "above %s's z = 0",
      subscriber_.getTopic().c_str(), params_.image_transport.c_str(),
      publisher_.getTopic().c_str(), params_.base_frame.c_str(), params_.min_height,
      params_.max_height, params_.ground_frame.c_str());
}

void DepthScanPublisher::refuse(const std::string& why, const std::string& detail) {
  const std::uint64_t n = ++refused_[why];
  ROS_WARN_THROTTLE(5.0, "jetbot_depth_scan: a depth image refused: %s%s (%llu so far for this)",
                    why.c_str(), detail.c_str(), static_cast<unsigned long long>(n));
}

void DepthScanPublisher::onDepth(const sensor_msgs::ImageConstPtr& depth,
                                 const sensor_msgs::CameraInfoConstPtr& info) {
  Eigen::Isometry3d optical, origin;
  try {
    const ros::Duration wait(params_.transform_timeout);
    optical = toIsometry(
        tf_.lookupTransform(params_.ground_frame, depth->header.frame_id, depth->header.stamp, wait)
            .transform);
    origin = toIsometry(
        tf_.lookupTransform(params_.ground_frame, params_.base_frame, depth->header.stamp, wait)
            .transform);
  } catch (const tf2::TransformException& e) {
    refuse("no transform from " + params_.ground_frame + " to '" + depth->header.frame_id +
               "' and " + params_.base_frame + " at its time",
           std::string(": ") + e.what());
    return;
  }
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = params_.base_frame;
  if (const std::string why = converter_.convert(*depth, *info, optical, origin, scan);
      !why.empty()) {
    refuse(why, "");
    return;
  }
  publisher_.publish(scan);
}

namespace {

/// With a checkpoint: the range and heights its scan was made with (a parameter given anyway
/// wins, with a warning naming both).
void takeTrainedScan(const ros::NodeHandle& pnh, DepthScanParams& p) {
  if (p.checkpoint.empty()) return;
  if (std::filesystem::is_directory(p.checkpoint)) {
    p.checkpoint = (std::filesystem::path(p.checkpoint) / "checkpoints/best.pt").string();
  }
  ppo::CheckpointMeta meta;
  try {
    meta = ppo::readCheckpointMeta(p.checkpoint);
    ppo::requireObservationContract(meta, p.checkpoint);
  } catch (const Error& e) {
    throwInvalid("checkpoint", p.checkpoint, e.what());
  }
  const ObserverSpec& trained = meta.spec.observer;
  if (trained.scan_source != "camera_depth" || trained.scan_heights.size() != 2 ||
      trained.scan_range.size() != 2) {
    throwInvalid("checkpoint", p.checkpoint,
                 "was not trained on a depth camera's scan (its scan_source is '" +
                     trained.scan_source + "', not camera_depth)");
  }
  const auto take = [&pnh](const char* name, double& value, double from, const char* field) {
    if (!pnh.hasParam(name)) {
      value = from;
    } else if (value != from) {
      ROS_WARN("jetbot_depth_scan: %s = %g overrides the checkpoint's %s = %g", name, value, field,
               from);
    }
  };
  take("min_height", p.min_height, trained.scan_heights[0], "scan_heights[0]");
  take("max_height", p.max_height, trained.scan_heights[1], "scan_heights[1]");
  if (!pnh.hasParam("range")) {
    p.range = trained.scan_range;
  } else if (p.range != trained.scan_range) {
    ROS_WARN("jetbot_depth_scan: range = %s overrides the checkpoint's scan_range = %s",
             listText(p.range).c_str(), listText(trained.scan_range).c_str());
  }
  checkFieldRules(p);
}

}  // namespace

int runDepthScanNode() {
  ros::NodeHandle nh, pnh("~");
  const std::optional<DepthScanParams> params =
      loadParams<DepthScanParams>(pnh, [&pnh](DepthScanParams& p) { takeTrainedScan(pnh, p); });
  if (!params) {
    ros::shutdown();
    return 1;
  }
  DepthScanPublisher publisher(nh, *params);
  ros::spin();
  return 0;
}

}  // namespace jetbot_rl
