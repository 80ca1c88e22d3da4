#pragma once

// A planar laser scanner on a link of the robot (docs/world.md), cast in each env's world. Its
// defaults are the robot description's Gazebo ray sensor block, where it has one; a parameter
// that is set wins.

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// Where a scan's ranges come from.
enum class ScanSource {
  kLaser,        ///< A planar laser scanner's rays.
  kCameraDepth,  ///< The batch camera's depth image (pointcloud_to_laserscan's reduction).
};

inline const EnumNameList<ScanSource>& enumNames(ScanSource) {
  static const EnumNameList<ScanSource> names{{ScanSource::kLaser, "laser"},
                                              {ScanSource::kCameraDepth, "camera_depth"}};
  return names;
}

/// The `scan/...` parameters; 0, -1 and [] stand for the robot description's value.
struct ScannerConfig {
  bool enabled = true;  ///< false: no scanner, even when the robot description declares one.
  ScanSource source = ScanSource::kLaser;  ///< Rays, or the camera's depth image.
  double min_height = 0.03;    ///< camera_depth: points below this above the ground are floor [m].
  double max_height = 0.5;     ///< camera_depth: points above this pass over the robot [m].
  std::string link;            ///< Link of the scanner; empty: the Gazebo ray sensor's.
  int samples = 0;             ///< Beams; 0: Gazebo's (without a block: 360).
  std::vector<double> angles;  ///< [min, max] [rad]; []: Gazebo's (without: [-pi, pi)).
  std::vector<double> range;   ///< [min, max] [m]; []: Gazebo's (without: [0.12, 3.5]).
  double noise_std = -1.0;     ///< Gaussian range noise [m]; -1: Gazebo's (without: 0).
  int update_every = 0;        ///< Control steps between scans; 0: from Gazebo's update_rate.
};

template <typename C, typename V>
IfConfig<C, ScannerConfig> visitFields(C& c, V&& v) {
  const Range<double> any{-1e4, 1e4, false, false, ""};
  v("scan/enabled", c.enabled, AnyValue{},
    "false: no scanner, even when the robot description declares one.");
  v("scan/source", c.source, AnyValue{},
    "laser: a planar laser scanner's rays (a Gazebo ray sensor or scan/link); camera_depth: the "
    "batch camera's depth image reduced to a scan (as jetbot_depth_scan does on a robot): every "
    "pixel's "
    "point between scan/min_height and scan/max_height above the ground counts for the sample "
    "nearest its bearing from the robot's origin, the nearest one wins (the forward field of "
    "view only; defaults: a sample per image column over the camera's horizontal field of view, "
    "its cadence, range [0.12, min(far clip, 3.5)] m).");
  v("scan/min_height", c.min_height, inRange(-10.0, 10.0, "m"),
    "camera_depth: points lower than this above the ground are the floor, not obstacles.");
  v("scan/max_height", c.max_height, inRange(-10.0, 10.0, "m"),
    "camera_depth: points higher than this above the ground pass over the robot.");
  v("scan/link", c.link, AnyValue{"", "empty: the Gazebo ray sensor's link"},
    "URDF link the scanner sits on (beams in its x-y plane, angle 0 along its x axis); no link "
    "and no Gazebo ray sensor: no scanner.");
  v("scan/samples", c.samples, inRange(0, 100000, "", "0: Gazebo's, else 360"),
    "Beams per scan, spread from min to max angle (Gazebo's spacing: (max - min) / (samples - "
    "1)).");
  v("scan/angles", c.angles, EachValue<double>{any},
    "[min_angle, max_angle] [rad], min < max; []: Gazebo's, else [-pi, pi - 2 pi / samples].");
  v("scan/range", c.range, EachValue<double>{any},
    "[range_min, range_max] [m], 0 <= min < max; []: Gazebo's, else [0.12, 3.5].");
  v("scan/noise_std", c.noise_std, atLeast(-1.0, "m", "-1: Gazebo's, else 0"),
    "Gaussian noise added to every range (from the env's own scan stream).");
  v("scan/update_every", c.update_every, inRange(0, 100000, "control steps"),
    "Control steps between scans; 0: from Gazebo's <update_rate> (round(1 / (rate x control "
    "step)), at least 1), else every step.");
}

/// The rules between ScannerConfig's fields: angles and range have 0 or 2 values.
void checkFieldRules(const ScannerConfig& config);

}  // namespace jetbot_rl
