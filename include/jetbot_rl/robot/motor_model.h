#pragma once

// An open-loop motor (docs/core.md, "The motor model"): the stock Jetbot's driver
// (dusty-nv/jetbot_ros motors.py) turns a wheel speed into a PWM duty without encoders, so what
// the wheel does depends on the motor: below a duty it does not turn (stiction), above 1 it
// saturates, and two motors never run at the same speed for the same duty (trim).

#include <algorithm>
#include <cmath>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// The motor model; off by default (targets drive the wheels' velocity servos directly).
struct MotorModelConfig {
  bool enabled = false;  ///< `motor_model`
  /// Wheel speed at duty 1 [rad/s]; 0: each dof's velocity limit. The stock Jetbot's 200 rpm
  /// motors: 20.944 rad/s.
  double max_wheel_speed = 0.0;
  /// Range of |duty| below which a wheel stops: [min, max] for every dof, or one [min, max] per
  /// dof in dof order ([min_0, max_0, min_1, max_1, ...]).
  std::vector<double> dead_zone{0.0, 0.0};
  /// Range of the factor on the duty, likewise for all dofs or per dof (e.g. a robot whose right
  /// motor is 5 % weaker: [1, 1, 0.95, 0.95]).
  std::vector<double> trim{1.0, 1.0};

  /// True when a reset draws per-dof dead zones and trims (the model is on and a range is not
  /// its default).
  bool drawsAtReset() const {
    const auto all = [](const std::vector<double>& v, double x) {
      return std::all_of(v.begin(), v.end(), [x](double y) { return y == x; });
    };
    return enabled && (!all(dead_zone, 0.0) || !all(trim, 1.0));
  }
  /// The range of `ranges` (dead_zone or trim) for dof `dof`: its own pair, or the one for all.
  static const double* rangeOf(const std::vector<double>& ranges, int dof) {
    return ranges.size() == 2 ? ranges.data() : ranges.data() + 2 * dof;
  }
};

template <typename C, typename V>
IfConfig<C, MotorModelConfig> visitFields(C& c, V&& v) {
  v("motor_model", c.enabled, AnyValue{},
    "Open-loop motor between the targets and the wheels: target -> duty, dead zone, saturation "
    "at 1, trim.");
  v("motor_max_wheel_speed", c.max_wheel_speed,
    atLeast(0.0, "rad/s", "0: each dof's velocity limit"),
    "Wheel speed at duty 1 (the stock Jetbot's 200 rpm motors: 20.944).");
  v("motor_dead_zone", c.dead_zone, intervalsOf(Range<double>{0.0, 1.0, false, true, "duty"}),
    "Range of |duty| below which a wheel stops, drawn per wheel at every reset.");
  v("motor_trim", c.trim, intervalsOf(positive()),
    "Range of the factor on each wheel's duty, drawn per wheel at every reset.");
}

/**
 * The wheel velocity target [rad/s] a motor gives for a commanded one `target` [rad/s]: the duty
 * target / max_wheel_speed [rad/s] is set to 0 below `dead_zone` (|duty|), saturated at +-1 and
 * multiplied by `trim`.
 */
inline double motorVelocityTarget(double target, double max_wheel_speed, double dead_zone,
                                  double trim) {
  double duty = target / max_wheel_speed;
  if (std::abs(duty) < dead_zone) duty = 0.0;
  duty = std::clamp(duty, -1.0, 1.0);
  return trim * duty * max_wheel_speed;
}

}  // namespace jetbot_rl
