#include "jetbot_rl/planning/speed_limit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {

void checkFieldRules(const SpeedLimitConfig& config) {
  if ((config.enabled || config.deployed) && !(config.stop_distance < config.slow_distance)) {
    std::ostringstream s;
    s << config.slow_distance << ": must be > speed_limit/stop_distance (" << config.stop_distance
      << ")";
    throwInvalid("speed_limit/slow_distance", s.str(), "the speed ramps up between them");
  }
}

SpeedLimitSpec makeSpeedLimitSpec(const SpeedLimitConfig& config, const RobotModel& robot,
                                  const ScannerSpec& scanner) {
  const char* field = config.enabled ? "speed_limit/enabled" : "speed_limit/deployed";
  if (scanner.body != 0) {
    throwInvalid(field, "true",
                 "the scanner's link '" + scanner.link +
                     "' moves on a joint: the path ahead is measured from a scanner fixed to the "
                     "root link");
  }
  const Eigen::Vector3d forward = scanner.pose_in_body.linear() * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(forward.y(), forward.x());
  if (std::abs(yaw) > 1e-3 || forward.head<2>().norm() < 0.99) {
    std::ostringstream s;
    s << "the scanner on '" << scanner.link << "' faces " << yaw
      << " rad from the root link's x axis (tilted or turned): the path ahead is measured from "
         "a scanner facing forward, level";
    throwInvalid(field, "true", s.str());
  }
  const Eigen::Vector3d at = scanner.pose_in_body.translation();
  SpeedLimitSpec spec;
  spec.front = robot.frontReach() - at.x();
  spec.left = robot.halfWidth() + config.margin - at.y();
  spec.right = -robot.halfWidth() - config.margin - at.y();
  spec.stop_distance = config.stop_distance;
  spec.slow_distance = config.slow_distance;
  return spec;
}

void takeSpeedLimit(const ObserverSpec& trained, const RobotModel& robot,
                    SpeedLimitConfig& config) {
  config.enabled = trained.speed_limit_distances.size() == 2;
  config.deployed = false;
  if (!config.enabled) return;
  config.stop_distance = trained.speed_limit_distances[0];
  config.slow_distance = trained.speed_limit_distances[1];
  // The path's width is the robot's plus twice the margin, wherever the scanner sits: the
  // training's margin, not this config's. A narrower robot than the checkpoint's keeps margin 0
  // (and the evaluator warns of the path's difference).
  const std::vector<double>& path = trained.speed_limit_path;
  if (path.size() == 3) config.margin = std::max(0.0, (path[1] - path[2]) / 2 - robot.halfWidth());
}

SpeedLimit::SpeedLimit(const SpeedLimitSpec& spec, int samples, double angle_min, double increment,
                       double range_min)
    : spec_(spec),
      samples_(samples),
      angle_min_(angle_min),
      increment_(increment),
      range_min_(range_min) {
  cos_.resize(static_cast<std::size_t>(std::max(samples, 0)));
  sin_.resize(cos_.size());
  for (int k = 0; k < samples; ++k) {
    const double a = angle_min + k * increment;
    cos_[k] = std::cos(a);
    sin_[k] = std::sin(a);
  }
}

double SpeedLimit::clearAhead(const float* ranges) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < samples_; ++k) {
    const float r = ranges[k];
    if (std::isnan(r) || r == std::numeric_limits<float>::infinity()) continue;
    // Too close to measure: as near as the scanner can say, which is where it would stop.
    const double range = std::isinf(r) ? range_min_ : static_cast<double>(r);
    const double x = range * cos_[k], y = range * sin_[k];
    if (y > spec_.left || y < spec_.right || x < spec_.front) continue;
    nearest = std::min(nearest, x - spec_.front);
  }
  return nearest;
}

double SpeedLimit::cap(const float* ranges, double v_max) const {
  return capAt(clearAhead(ranges), v_max);
}

double SpeedLimit::capAt(double d, double v_max) const {
  if (!(d < spec_.slow_distance)) return v_max;
  const double f = (d - spec_.stop_distance) / (spec_.slow_distance - spec_.stop_distance);
  return v_max * std::clamp(f, 0.0, 1.0);
}

bool SpeedLimit::fits(const ScanView& scan, double range_min) const {
  return scan.samples == samples_ && scan.angle_min == angle_min_ && scan.increment == increment_ &&
         range_min == range_min_;
}

}  // namespace jetbot_rl
