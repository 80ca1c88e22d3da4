#pragma once

#include <string>

namespace jetbot_rl {

/// Where a dof's limit comes from.
enum class LimitSource {
  kUrdf,       ///< The joint's <limit> in the URDF.
  kParameter,  ///< The configuration (`wheel_velocity_limit`, `effort_limit`), which wins.
  kGazebo,     ///< The Gazebo diff drive plugin's <wheelTorque>, which wins over the URDF.
};

/// A driven joint's limits in use and where they come from (for the start-up echo).
struct DofLimits {
  std::string name;             ///< Joint name.
  double velocity_limit = 0.0;  ///< Targets are clamped to +/- this [rad/s].
  double effort_limit = 0.0;    ///< The drive's torque limit [N m].
  LimitSource velocity_source = LimitSource::kUrdf;
  LimitSource effort_source = LimitSource::kUrdf;
  double urdf_velocity_limit = 0.0;  ///< The URDF's <limit velocity> [rad/s]; 0: none.
  double urdf_effort_limit = 0.0;    ///< The URDF's <limit effort> [N m]; 0: none.
};

/// One line for the start-up INFO echo, e.g. "wheel_left_joint: velocity limit 6 rad/s
/// (wheel_velocity_limit; URDF: none), effort limit 0.3 N m (URDF)".
std::string describeDofLimits(const DofLimits& limits);

}  // namespace jetbot_rl
