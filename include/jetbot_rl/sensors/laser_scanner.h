#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/sensors/scanner_config.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// A scanner in use: ScannerConfig resolved against the robot description's Gazebo block.
struct ScannerSpec {
  std::string link;  ///< URDF link (the LaserScan's frame).
  int body = 0;      ///< The robot body the link belongs to.
  /// The beams' frame in the body's link frame (the link's offset and the Gazebo <pose>).
  Eigen::Isometry3d pose_in_body = Eigen::Isometry3d::Identity();
  int samples = 360;
  double min_angle = 0.0, max_angle = 0.0;   ///< [rad]
  double range_min = 0.0, range_max = 0.0;   ///< [m]
  double noise_mean = 0.0, noise_std = 0.0;  ///< [m]
  int update_every = 1;                      ///< [control steps]
  /// Where the ranges come from; camera_depth: the camera's points between these heights above
  /// the ground [m] (scan/min_height, scan/max_height).
  ScanSource source = ScanSource::kLaser;
  double min_height = 0.0, max_height = 0.0;
  /// Per value, where it came from: "scan/<name>", "Gazebo" or "default".
  std::string samples_from, angles_from, range_from, noise_from, update_from, link_from;

  /// Angle between beams: (max - min) / (samples - 1), Gazebo's spacing (0 for one beam) [rad].
  double angleIncrement() const {
    return samples > 1 ? (max_angle - min_angle) / (samples - 1) : 0.0;
  }
};

/// The scanner `config` gives on `robot`, whose control step is `control_dt` [s]: nothing when
/// it is disabled or names no link and the robot declares no ray sensor. Throws ConfigError
/// naming the field (scan/link not in the URDF, samples < 1, min >= max, range_min < 0) and its
/// value, and where a value came from (the Gazebo block) when that is what is wrong. `config`'s
/// own rules are checked at the boundary (EnvConfig::validate()).
std::optional<ScannerSpec> resolveScanner(const ScannerConfig& config, const RobotModel& robot,
                                          double control_dt);

/// The height of the scanner's beams above the ground with the robot at rest, joints at zero [m].
double scannerHeight(const RobotModel& robot, const ScannerSpec& spec);

/// One line for the start-up echo: link, beams, angles, range, noise, update, and sources.
std::string describeScanner(const ScannerSpec& spec);

/// What a beam that hits nothing within range_max reads (REP 117).
constexpr float kNoReturn = std::numeric_limits<float>::infinity();
/// What a beam whose range is below range_min reads (REP 117).
constexpr float kTooClose = -std::numeric_limits<float>::infinity();

/**
 * Casts one scan from `sensor` (the beams' frame in the env frame: beam k along angle min_angle +
 * k x increment in its x-y plane) against the static world (map cells, walls), `obstacles` and
 * `movers` (an env's moving obstacles where they stand, or none): the ground and the robot are
 * never tested. Writes `spec.samples` ranges to `ranges`: the
 * distance to the first surface plus Gaussian noise (mean, std) from `noise`, +inf (kNoReturn)
 * beyond range_max, -inf (kTooClose) below range_min (REP 117).
 */
void castScan(const ScannerSpec& spec, const WorldModel* world,
              const std::vector<Obstacle>& obstacles, const Eigen::Isometry3d& sensor, Rng& noise,
              float* ranges, const std::vector<Obstacle>* movers = nullptr);

/// A reading as a task sees it: +inf as range_max, -inf as range_min (finite, in [min, max]).
inline float finiteRange(float range, const ScannerSpec& spec) {
  if (range == kNoReturn) return static_cast<float>(spec.range_max);
  if (range == kTooClose) return static_cast<float>(spec.range_min);
  return range;
}

}  // namespace jetbot_rl
