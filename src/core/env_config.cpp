#include "jetbot_rl/env_config.h"

#include <cmath>
#include <set>
#include <sstream>
#include <thread>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

void EnvConfig::validate() const {
  if (num_envs < 1 || num_envs > 1000000)
    throwInvalid("num_envs", num_envs, "must be in [1, 1000000]");
  if (!std::isfinite(env_spacing) || env_spacing <= 0.0 || env_spacing > 1000.0) {
    throwInvalid("env_spacing", env_spacing, "must be in (0, 1000] m");
  }
  if (!std::isfinite(physics_dt) || physics_dt <= 0.0 || physics_dt > 0.1) {
    throwInvalid("physics_dt", physics_dt, "must be in (0, 0.1] s");
  }
  if (decimation < 1 || decimation > 1000)
    throwInvalid("decimation", decimation, "must be in [1, 1000]");
  if (!std::isfinite(episode_length_s) || episode_length_s <= 0.0) {
    throwInvalid("episode_length_s", episode_length_s, "must be positive");
  }
  const double steps = episode_length_s / controlDt();
  if (steps < 2.0 || steps > 1e9) {
    throwInvalid("episode_length_s", episode_length_s,
                 "must last between 2 and 1e9 control steps of physics_dt * decimation");
  }
  if (dof_names.empty()) throwInvalid("dof_names", "[]", "must name at least one joint");
  std::set<std::string> unique;
  for (const auto& name : dof_names) {
    if (name.empty()) throwInvalid("dof_names", "''", "joint names must not be empty");
    if (!unique.insert(name).second) throwInvalid("dof_names", name, "is listed twice");
  }
  if (num_threads < 0 || num_threads > 1024) {
    throwInvalid("num_threads", num_threads, "must be in [0, 1024] (0: all cores)");
  }
  if (!std::isfinite(drive_gain) || drive_gain <= 0.0) {
    throwInvalid("drive_gain", drive_gain, "must be positive");
  }
  if (!std::isfinite(effort_limit) || effort_limit < 0.0) {
    throwInvalid("effort_limit", effort_limit, "must be >= 0 (0: the URDF effort limit)");
  }
  if (solver_iterations < 1 || solver_iterations > 1000) {
    throwInvalid("solver_iterations", solver_iterations, "must be in [1, 1000]");
  }
  if (!std::isfinite(wheel_velocity_limit) || wheel_velocity_limit < 0.0) {
    throwInvalid("wheel_velocity_limit", wheel_velocity_limit,
                 "must be >= 0 rad/s (0: the URDF <limit velocity>)");
  }
  if (!std::isfinite(caster_friction) || caster_friction < 0.0) {
    throwInvalid("caster_friction", caster_friction, "must be >= 0");
  }
  if (!std::isfinite(wheel_radius) || wheel_radius < 0.0) {
    throwInvalid("wheel_radius", wheel_radius, "must be >= 0 m (0: derived from the URDF)");
  }
  if (!std::isfinite(wheel_separation) || wheel_separation < 0.0) {
    throwInvalid("wheel_separation", wheel_separation, "must be >= 0 m (0: derived from the URDF)");
  }
}

int EnvConfig::maxEpisodeLength() const {
  return static_cast<int>(std::ceil(episode_length_s / controlDt()));
}

int EnvConfig::resolvedThreads() const {
  if (num_threads > 0) return num_threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace jetbot_rl
