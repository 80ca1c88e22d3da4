#pragma once

// The forward speed limit near what the scan sees ahead (docs/navigation.md#the-speed-limit): a
// collision monitor between the policy and the wheels, as Nav2's slows a base before what lies in
// its path. The simulated env and the deploy node cap a twist's v with this one class, so a
// policy trained behind it drives behind it on a robot.

#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/sensors/scan_reading.h"

namespace jetbot_rl {

class RobotModel;
struct ObserverSpec;
struct ScannerSpec;

/// The `speed_limit/...` parameters (off by default).
struct SpeedLimitConfig {
  bool enabled = false;         ///< Cap a twist action's forward v by the scan ahead.
  bool deployed = false;        ///< The checkpoint names the limit, which this env does not apply.
  double stop_distance = 0.1;   ///< v is 0 with an obstacle this close ahead of the front [m].
  double slow_distance = 0.25;  ///< v is uncapped with none this close [m].
  double margin = 0.005;        ///< Added to the robot's half width on either side [m].
};

template <typename C, typename V>
IfConfig<C, SpeedLimitConfig> visitFields(C& c, V&& v) {
  v("speed_limit/enabled", c.enabled, AnyValue{},
    "true: a twist action's forward v is capped by the nearest scan reading in the robot's path "
    "ahead (its width plus speed_limit/margin, from its front): 0 at speed_limit/stop_distance, "
    "the action's bound at speed_limit/slow_distance, linear between; turning and reversing are "
    "not capped. Needs action_space twist and a scanner on the root link facing forward. The "
    "checkpoint carries it and the deploy node caps the same.");
  v("speed_limit/deployed", c.deployed, AnyValue{},
    "true: the env does not cap (unless speed_limit/enabled), but its spec, and so the "
    "checkpoint, names the limit: the policy learns without it to keep its own distance, and "
    "the evaluation tools and the deploy node drive it behind the limit, which catches what it "
    "misses. Needs what speed_limit/enabled needs.");
  v("speed_limit/stop_distance", c.stop_distance, inRange(0.0, 10.0, "m"),
    "Forward v is 0 with a reading this close ahead of the robot's front (a reading of -inf, "
    "closer than the scanner's range_min, counts as one at range_min along its beam).");
  v("speed_limit/slow_distance", c.slow_distance, inRange(0.0, 10.0, "m"),
    "Forward v is uncapped with no reading this close ahead of the front; > stop_distance.");
  v("speed_limit/margin", c.margin, inRange(0.0, 1.0, "m"),
    "The path ahead is the robot's collision shapes' width plus this on either side.");
}

/// stop_distance < slow_distance when enabled or deployed; ConfigError naming the fields and
/// values.
void checkFieldRules(const SpeedLimitConfig& config);

/// The limit as the checkpoint carries it: the path ahead in the scanner's frame and the distances.
struct SpeedLimitSpec {
  double front = 0.0;          ///< x of the robot's front [m].
  double left = 0.0;           ///< y of its left side plus the margin [m].
  double right = 0.0;          ///< y of its right side minus the margin [m].
  double stop_distance = 0.0;  ///< [m] from the front.
  double slow_distance = 0.0;  ///< [m] from the front; 0: no limit.

  bool enabled() const { return slow_distance > 0.0; }
};

/// The spec of `config` for `robot` seen by `scanner` (its path ahead from the collision shapes):
/// ConfigError naming speed_limit/enabled when the scanner is on a moving link or does not face
/// the root link's x axis.
SpeedLimitSpec makeSpeedLimitSpec(const SpeedLimitConfig& config, const RobotModel& robot,
                                  const ScannerSpec& scanner);

/// Sets `config` to drive as `trained` (a checkpoint's contract) will drive: behind its limit,
/// with its distances and a margin giving `robot` a path as wide as the checkpoint's, or without
/// one (an evaluation measures the policy as it will drive, also when it trained without the
/// limit: speed_limit/deployed).
void takeSpeedLimit(const ObserverSpec& trained, const RobotModel& robot, SpeedLimitConfig& config);

/// Caps forward speed for scans of one geometry (its samples' directions computed once).
class SpeedLimit {
 public:
  /// For scans of `samples` readings from `angle_min` by `increment` [rad], range_min [m].
  SpeedLimit(const SpeedLimitSpec& spec, int samples, double angle_min, double increment,
             double range_min);

  /// The fastest forward v [m/s] allowed, as a fraction of `v_max` [m/s], given one scan of
  /// this geometry (REP 117 values: NaN and +inf see nothing, -inf one at range_min).
  double cap(const float* ranges, double v_max) const;
  /// The same for a known clearAhead() distance `clear_ahead` [m] (one scan's pass for both).
  double capAt(double clear_ahead, double v_max) const;
  /// Distance from the front to the nearest reading in the path ahead [m]; +inf: none.
  double clearAhead(const float* ranges) const;
  /// Whether scans of this geometry are what it was made for.
  bool fits(const ScanView& scan, double range_min) const;

 private:
  SpeedLimitSpec spec_;
  int samples_;
  double angle_min_, increment_, range_min_;
  std::vector<double> cos_, sin_;
};

}  // namespace jetbot_rl
