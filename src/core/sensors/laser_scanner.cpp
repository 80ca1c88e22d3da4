#include "jetbot_rl/sensors/laser_scanner.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

template <typename T>
std::string text(T v) {
  std::ostringstream s;
  writeValue(s, v);
  return s.str();
}

}  // namespace

void checkFieldRules(const ScannerConfig& c) {
  for (const auto& [name, v] :
       {std::make_pair("scan/angles", &c.angles), std::make_pair("scan/range", &c.range)}) {
    if (!v->empty() && v->size() != 2) throwInvalid(name, listText(*v), "must be [min, max] or []");
  }
}

std::optional<ScannerSpec> resolveScanner(const ScannerConfig& config, const RobotModel& robot,
                                          double control_dt) {
  if (!config.enabled) return std::nullopt;
  const auto& ray = robot.gazebo().ray;
  ScannerSpec spec;
  spec.link = config.link.empty() ? (ray ? ray->link : "") : config.link;
  spec.link_from = config.link.empty() ? "Gazebo" : "scan/link";
  if (spec.link.empty()) return std::nullopt;
  Eigen::Isometry3d offset;
  if (!robot.findLink(spec.link, spec.body, offset)) {
    throwInvalid("scan/link", "'" + spec.link + "'", "is not a link of the robot description");
  }
  // The Gazebo block gives the defaults of the scanner on its own link.
  const GazeboRaySensor* g = ray && ray->link == spec.link ? &*ray : nullptr;
  const std::string gazebo = g ? " (from the Gazebo ray sensor '" + g->name + "' of link '" +
                                     g->link + "'; set the parameter to override it)"
                               : "";
  spec.pose_in_body = offset * (g ? g->pose : Eigen::Isometry3d::Identity());

  const auto pick = [&](bool set, const char* name, bool from_gazebo) {
    return set ? std::string(name) : from_gazebo ? std::string("Gazebo") : std::string("default");
  };
  spec.samples = config.samples > 0 ? config.samples : g ? g->samples : 360;
  spec.samples_from = pick(config.samples > 0, "scan/samples", g);
  if (spec.samples < 1 || spec.samples > 100000) {
    throwInvalid("scan/samples", spec.samples,
                 "must be in [1, 100000]" + (config.samples > 0 ? std::string() : gazebo));
  }
  // A [min, max] pair: the parameter's, else the Gazebo block's, else the default.
  const auto pair = [g](const std::vector<double>& set, double gazebo_min, double gazebo_max,
                        double default_min, double default_max, double& min, double& max) {
    min = set.size() == 2 ? set[0] : g ? gazebo_min : default_min;
    max = set.size() == 2 ? set[1] : g ? gazebo_max : default_max;
  };
  pair(config.angles, g ? g->min_angle : 0.0, g ? g->max_angle : 0.0, -kPi,
       kPi - 2.0 * kPi / spec.samples, spec.min_angle, spec.max_angle);
  spec.angles_from = pick(config.angles.size() == 2, "scan/angles", g);
  const bool angles_ok =
      std::isfinite(spec.min_angle) && std::isfinite(spec.max_angle) &&
      (spec.samples == 1 ? spec.min_angle <= spec.max_angle : spec.min_angle < spec.max_angle);
  if (!angles_ok) {
    throwInvalid(
        "scan/angles", "[" + text(spec.min_angle) + ", " + text(spec.max_angle) + "]",
        "must be [min, max] with min < max" + (config.angles.size() == 2 ? std::string() : gazebo));
  }
  pair(config.range, g ? g->range_min : 0.0, g ? g->range_max : 0.0, 0.12, 3.5, spec.range_min,
       spec.range_max);
  spec.range_from = pick(config.range.size() == 2, "scan/range", g);
  if (!(spec.range_min >= 0.0 && spec.range_min < spec.range_max &&
        std::isfinite(spec.range_max))) {
    throwInvalid("scan/range", "[" + text(spec.range_min) + ", " + text(spec.range_max) + "]",
                 "must be [min, max] with 0 <= min < max, finite" +
                     (config.range.size() == 2 ? std::string() : gazebo));
  }
  if (config.noise_std >= 0.0) {
    spec.noise_std = config.noise_std;
  } else if (g) {
    spec.noise_mean = g->noise_mean;
    spec.noise_std = g->noise_stddev;
  }
  spec.noise_from = pick(config.noise_std >= 0.0, "scan/noise_std", g);
  if (!(spec.noise_std >= 0.0) || !std::isfinite(spec.noise_std) ||
      !std::isfinite(spec.noise_mean)) {
    throwInvalid("scan/noise_std", spec.noise_std, "must be >= 0, finite" + gazebo);
  }
  if (config.update_every > 0) {
    spec.update_every = config.update_every;
  } else if (g && g->update_rate > 0.0) {
    if (!std::isfinite(g->update_rate)) {
      throwInvalid("scan/update_every", g->update_rate, "the update rate must be finite" + gazebo);
    }
    spec.update_every =
        std::max(1, static_cast<int>(std::lround(1.0 / (g->update_rate * control_dt))));
  }
  spec.update_from = pick(config.update_every > 0, "scan/update_every", g && g->update_rate > 0);
  return spec;
}

std::string describeScanner(const ScannerSpec& s) {
  std::ostringstream out;
  out << (s.source == ScanSource::kCameraDepth
              ? "scan from the camera's depth image (points "
                "between " +
                    text(s.min_height) + " and " + text(s.max_height) + " m above the ground)"
              : std::string("laser scanner"))
      << " on link '" << s.link << "' (" << s.link_from << "): " << s.samples << " beams ("
      << s.samples_from << ") over [" << text(s.min_angle) << ", " << text(s.max_angle) << "] rad ("
      << s.angles_from << "), range [" << text(s.range_min) << ", " << text(s.range_max) << "] m ("
      << s.range_from << "), noise mean " << text(s.noise_mean) << " std " << text(s.noise_std)
      << " m (" << s.noise_from << "), every " << s.update_every << " control steps ("
      << s.update_from << ")";
  return out.str();
}

double scannerHeight(const RobotModel& robot, const ScannerSpec& spec) {
  Eigen::Isometry3d pose = spec.pose_in_body;
  for (int b = spec.body; b > 0; b = robot.bodies()[b].parent) {
    pose = robot.bodies()[b].joint_origin * pose;
  }
  return robot.restHeight() + pose.translation().z();
}

}  // namespace jetbot_rl
