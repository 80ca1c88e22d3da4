#pragma once

// Domain randomisation (docs/core.md, "Domain randomisation"): per-env physical parameters drawn at
// every reset from the env's own seeded stream, noise on actions and observations, action delay.
// Off by default: then nothing is drawn and every trajectory is bit for bit the one without it.

#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// The ranges drawn from at every reset ([min, max], uniform; [v, v] is the constant v) and the
/// noise. Defaults are off.
struct RandomizationConfig {
  std::vector<double> mass_scale{1.0, 1.0};        ///< Chassis (root body) mass and inertia factor.
  std::vector<double> wheel_friction{1.0, 1.0};    ///< Wheel-ground friction coefficient.
  std::vector<double> drive_gain_scale{1.0, 1.0};  ///< Factor on drive_gain.
  std::vector<double> effort_limit_scale{1.0, 1.0};  ///< Factor on every dof's effort limit.
  std::vector<double> wheel_radius_scale{1.0, 1.0};  ///< Factor on the wheels' collision shapes.
  std::vector<double> initial_yaw{0.0, 0.0};         ///< Heading at reset [rad].
  std::vector<double> initial_speed{0.0, 0.0};       ///< Forward speed at reset [m/s].
  std::vector<int> action_delay_steps{0, 0};  ///< Control steps before a target takes effect.
  double action_noise_std = 0.0;              ///< Gaussian noise on every target [rad/s].
  /// Gaussian noise on the observations: empty = none, one value for every component, or one per
  /// component (task units).
  std::vector<double> obs_noise_std;

  /// True when a reset draws (and applies) per-env values: a range differs from its default.
  bool drawsAtReset() const;
  /// True when any noise is on (drawn from each env's noise stream at every step).
  bool hasNoise() const;
};

/// The fields of RandomizationConfig with their rules (see config_fields.h).
template <typename C, typename V>
IfConfig<C, RandomizationConfig> visitFields(C& c, V&& v) {
  const double kInf = std::numeric_limits<double>::infinity();
  v("mass_scale", c.mass_scale, intervalOf(positive()),
    "Chassis (root body) mass and inertia factor, drawn per env at every reset.");
  v("wheel_friction", c.wheel_friction, intervalOf(atLeast(0.0)),
    "Wheel-ground friction coefficient, drawn per env at every reset.");
  v("drive_gain_scale", c.drive_gain_scale, intervalOf(positive()),
    "Factor on drive_gain, drawn per env at every reset.");
  v("effort_limit_scale", c.effort_limit_scale, intervalOf(positive()),
    "Factor on every wheel's effort limit, drawn per env at every reset.");
  v("wheel_radius_scale", c.wheel_radius_scale, intervalOf(Range<double>{0.0, 10.0, true}),
    "Factor on the wheels' collision shapes, drawn per env at every reset.");
  v("initial_yaw", c.initial_yaw, intervalOf(inRange(-10.0, 10.0, "rad")),
    "Heading at reset, drawn per env.");
  v("initial_speed", c.initial_speed, intervalOf(inRange(-10.0, 10.0, "m/s")),
    "Forward speed at reset, drawn per env.");
  v("action_delay_steps", c.action_delay_steps, intervalOf(inRange(0, 1000, "control steps")),
    "Control steps before a target acts, drawn per env at every reset.");
  v("action_noise_std", c.action_noise_std, atLeast(0.0, "rad/s"),
    "Gaussian noise on every wheel target before clamping.");
  v("obs_noise_std", c.obs_noise_std,
    EachValue<double>{Range<double>{0.0, kInf, false, false, "task units", ""}},
    "Gaussian noise on the observations: [] none, one std for all, or one per component.");
}

/// The values one env drew at its last reset (the defaults when randomisation is off): one type
/// with one field list (below) for the draw (each scalar from RandomizationConfig's range of the
/// same name, in the list's order), the env's physics, EnvRandomization.msg and its docs.
struct RandomizationDraw {
  double mass_scale = 1.0;
  double wheel_friction = 1.0;
  double drive_gain_scale = 1.0;
  double effort_limit_scale = 1.0;
  double wheel_radius_scale = 1.0;
  double initial_yaw = 0.0;             ///< [rad]
  double initial_speed = 0.0;           ///< [m/s]
  int action_delay_steps = 0;           ///< [control steps]
  std::vector<double> motor_dead_zone;  ///< Per dof [duty]; empty when the motor model is off.
  std::vector<double> motor_trim;       ///< Per dof; empty when the motor model is off.
};

/// The fields of RandomizationDraw, in the order they are drawn (docs/core.md, "Domain
/// randomisation": changing it changes every randomised trajectory).
template <typename C, typename V>
IfConfig<C, RandomizationDraw> visitFields(C& c, V&& v) {
  v("mass_scale", c.mass_scale, AnyValue{}, "Chassis (root body) mass and inertia factor.");
  v("wheel_friction", c.wheel_friction, AnyValue{}, "Wheel-ground friction coefficient.");
  v("drive_gain_scale", c.drive_gain_scale, AnyValue{}, "Factor on drive_gain.");
  v("effort_limit_scale", c.effort_limit_scale, AnyValue{}, "Factor on every dof's effort limit.");
  v("wheel_radius_scale", c.wheel_radius_scale, AnyValue{},
    "Factor on the wheels' collision shapes.");
  v("initial_yaw", c.initial_yaw, AnyValue{"rad"}, "Heading at the reset.");
  v("initial_speed", c.initial_speed, AnyValue{"m/s"}, "Forward speed at the reset.");
  v("action_delay_steps", c.action_delay_steps, AnyValue{"control steps"},
    "Control steps before a target takes effect.");
  v("motor_dead_zone", c.motor_dead_zone, AnyValue{"duty"},
    "Per dof (motor model): |duty| below it stops the wheel; empty when the model is off.");
  v("motor_trim", c.motor_trim, AnyValue{},
    "Per dof (motor model): factor on the duty; empty when the model is off.");
}

}  // namespace jetbot_rl
