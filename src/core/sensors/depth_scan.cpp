#include "jetbot_rl/sensors/depth_scan.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

// The default range's ends [m]: a laser's nearest, and no farther than the navigation scan's.
constexpr double kDefaultRangeMin = 0.12;
constexpr double kDefaultRangeMax = 3.5;

}  // namespace

ScannerSpec resolveDepthScanner(const ScannerConfig& config, const RobotModel& robot,
                                const CameraSpec& camera) {
  if (!camera.depth) {
    throwInvalid("scan/source", "camera_depth",
                 "needs the camera's depth image: give camera/images with depth (camera '" +
                     camera.name + "' makes none)");
  }
  if (!config.link.empty()) {
    throwInvalid("scan/link", "'" + config.link + "'",
                 "must be empty with scan/source camera_depth (the scan lies about the root "
                 "link, from the camera's points)");
  }
  if (!(config.min_height < config.max_height)) {
    std::ostringstream rule;
    rule << "must be below scan/max_height " << config.max_height;
    throwInvalid("scan/min_height", config.min_height, rule.str());
  }
  const CameraIntrinsics& in = camera.intrinsics;
  ScannerSpec spec;
  spec.link = robot.bodies().front().link_name;
  spec.link_from = "the root link (scan/source camera_depth)";
  spec.body = 0;
  spec.samples = config.samples > 0 ? config.samples : in.width;
  spec.samples_from = config.samples > 0 ? "scan/samples" : "the camera's width";
  const double half = 0.5 * in.horizontal_fov;
  spec.min_angle = config.angles.size() == 2 ? config.angles[0] : -half;
  spec.max_angle = config.angles.size() == 2 ? config.angles[1] : half;
  spec.angles_from = config.angles.size() == 2 ? "scan/angles" : "the camera's field of view";
  if (!(spec.min_angle < spec.max_angle) || !std::isfinite(spec.min_angle) ||
      !std::isfinite(spec.max_angle)) {
    throwInvalid("scan/angles", listText(config.angles), "must be [min, max] with min < max");
  }
  spec.range_min = config.range.size() == 2 ? config.range[0] : kDefaultRangeMin;
  spec.range_max = config.range.size() == 2 ? config.range[1] : std::min(in.far, kDefaultRangeMax);
  spec.range_from = config.range.size() == 2 ? "scan/range" : "default";
  if (!(spec.range_min >= 0.0 && spec.range_min < spec.range_max &&
        std::isfinite(spec.range_max))) {
    throwInvalid("scan/range", listText(config.range),
                 "must be [min, max] with 0 <= min < max, finite");
  }
  if (config.noise_std > 0.0) {
    throwInvalid("scan/noise_std", config.noise_std,
                 "must be -1 or 0 with scan/source camera_depth (the depth's noise is the "
                 "camera's)");
  }
  spec.noise_from = "none (the camera's depth)";
  spec.update_every = camera.update_every;
  spec.update_from = "the camera's";
  spec.source = ScanSource::kCameraDepth;
  spec.min_height = config.min_height;
  spec.max_height = config.max_height;
  return spec;
}

std::optional<ScannerSpec> resolveScan(const ScannerConfig& config, const RobotModel& robot,
                                       const std::vector<CameraSpec>& cameras, double control_dt) {
  if (!config.enabled || config.source == ScanSource::kLaser) {
    return resolveScanner(config, robot, control_dt);
  }
  if (cameras.empty()) {
    throwInvalid("scan/source", "camera_depth", "needs a camera (none is declared or enabled)");
  }
  return resolveDepthScanner(config, robot, cameras.front());
}

void depthToScan(const ScannerSpec& spec, const CameraModel& model, const float* depth,
                 const Eigen::Isometry3d& optical, const Eigen::Isometry3d& origin, float* ranges) {
  depthToScan(spec, model.pixelRays(), depth, optical, origin, ranges);
}

void depthToScan(const ScannerSpec& spec, const std::vector<Eigen::Vector3f>& rays,
                 const float* depth, const Eigen::Isometry3d& optical,
                 const Eigen::Isometry3d& origin, float* ranges) {
  const double min_height = spec.min_height, max_height = spec.max_height;
  std::fill(ranges, ranges + spec.samples, kNoReturn);
  const Eigen::Matrix3d r = origin.linear();
  const double heading = std::atan2(r(1, 0), r(0, 0));
  const Eigen::Vector2d centre = origin.translation().head<2>();
  const double c = std::cos(heading), s = std::sin(heading);
  const double increment = spec.angleIncrement();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const double d = depth[i];
    if (!std::isfinite(d)) continue;  // nothing within the clip (REP 118's +-inf)
    const Eigen::Vector3d p = optical * (rays[i].cast<double>() * d);
    if (p.z() < min_height || p.z() > max_height) continue;
    const Eigen::Vector2d w = p.head<2>() - centre;
    const double x = c * w.x() + s * w.y(), y = -s * w.x() + c * w.y();
    const double bearing = std::atan2(y, x);
    const double k = increment > 0.0 ? std::round((bearing - spec.min_angle) / increment) : 0.0;
    if (k < 0.0 || k >= spec.samples) continue;
    const double range = std::hypot(x, y);
    if (range > spec.range_max) continue;
    float& sample = ranges[static_cast<std::size_t>(k)];
    const float value = range < spec.range_min ? kTooClose : static_cast<float>(range);
    if (value == kTooClose || (sample != kTooClose && value < sample)) sample = value;
  }
}

std::vector<Eigen::Vector3f> pinholeRays(int width, int height, double fx, double fy, double cx,
                                         double cy, const std::vector<double>& plumb_bob) {
  if (!(fx > 0.0 && fy > 0.0 && std::isfinite(fx) && std::isfinite(fy) && std::isfinite(cx) &&
        std::isfinite(cy))) {
    std::ostringstream value;
    value << "[fx " << fx << ", fy " << fy << ", cx " << cx << ", cy " << cy << "]";
    throwInvalid("K", value.str(), "must hold a pinhole camera: fx, fy > 0, all finite");
  }
  if (!plumb_bob.empty() && plumb_bob.size() != 5) {
    throwInvalid("D", listText(plumb_bob), "must be plumb_bob's 5 coefficients (or none)");
  }
  // The distortion undone as CameraModel undoes it (Gazebo's Brown-Conrady model is plumb_bob);
  // the model's own focal length and centre are not used.
  CameraIntrinsics c;
  c.width = width;
  c.height = height;
  c.horizontal_fov = 2.0 * std::atan(width / 2.0 / fx);
  if (plumb_bob.size() == 5) {
    c.k1 = plumb_bob[0];
    c.k2 = plumb_bob[1];
    c.p1 = plumb_bob[2];
    c.p2 = plumb_bob[3];
    c.k3 = plumb_bob[4];
  }
  const CameraModel model(c, "camera_info/");
  std::vector<Eigen::Vector3f> rays;
  rays.reserve(static_cast<std::size_t>(width) * height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector2d p = model.undistort(Eigen::Vector2d((u - cx) / fx, (v - cy) / fy));
      rays.push_back(Eigen::Vector3d(p.x(), p.y(), 1.0).cast<float>());
    }
  }
  return rays;
}

}  // namespace jetbot_rl
