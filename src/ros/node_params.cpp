#include "jetbot_rl/ros/node_params.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/param_reader.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {

std::string modeName(EnvMode mode) { return mode == EnvMode::kRealtime ? "realtime" : "lockstep"; }

NodeParams loadNodeParams(const ros::NodeHandle& pnh) {
  NodeParams p;
  EnvConfig& e = p.env;
  readParam(pnh, "num_envs", e.num_envs);
  readParam(pnh, "env_spacing", e.env_spacing);
  readParam(pnh, "physics_dt", e.physics_dt);
  readParam(pnh, "decimation", e.decimation);
  readParam(pnh, "episode_length_s", e.episode_length_s);
  readParam(pnh, "dof_names", e.dof_names);
  int seed = static_cast<int>(e.seed);
  readParam(pnh, "seed", seed);
  if (seed < 0) throwInvalid("seed", seed, "must be >= 0");
  e.seed = static_cast<std::uint64_t>(seed);
  readParam(pnh, "num_threads", e.num_threads);
  readParam(pnh, "drive_gain", e.drive_gain);
  readParam(pnh, "effort_limit", e.effort_limit);
  readParam(pnh, "solver_iterations", e.solver_iterations);

  readParam(pnh, "task", p.task);
  readParam(pnh, "reward", p.reward);
  std::string mode = modeName(p.mode);
  readParam(pnh, "mode", mode);
  if (mode == "lockstep") {
    p.mode = EnvMode::kLockstep;
  } else if (mode == "realtime") {
    p.mode = EnvMode::kRealtime;
  } else {
    throwInvalid("mode", "'" + mode + "'", "must be 'lockstep' or 'realtime'");
  }
  readParam(pnh, "real_time_factor", p.real_time_factor);
  readParam(pnh, "action_timeout", p.action_timeout);
  readParam(pnh, "publish_clock", p.publish_clock);
  readParam(pnh, "tf_envs", p.tf_envs);
  readParam(pnh, "tf_rate", p.tf_rate);
  readParam(pnh, "markers", p.markers);
  validateNodeParams(p);
  return p;
}

void validateNodeParams(const NodeParams& p) {
  p.env.validate();
  makeTask(p.task, p.reward);
  if (!std::isfinite(p.real_time_factor) || p.real_time_factor <= 0.0 ||
      p.real_time_factor > 1000.0) {
    throwInvalid("real_time_factor", p.real_time_factor, "must be in (0, 1000]");
  }
  if (!std::isfinite(p.action_timeout) || p.action_timeout <= 0.0) {
    throwInvalid("action_timeout", p.action_timeout, "must be a positive number of seconds");
  }
  if (p.tf_envs < 0) throwInvalid("tf_envs", p.tf_envs, "must be >= 0 (0: no tf)");
  if (!std::isfinite(p.tf_rate) || p.tf_rate <= 0.0) {
    throwInvalid("tf_rate", p.tf_rate, "must be a positive rate in Hz of simulation time");
  }
}

std::string describeNodeParams(const NodeParams& p) {
  const EnvConfig& e = p.env;
  std::ostringstream s;
  s << "num_envs: " << e.num_envs << "\nenv_spacing: " << e.env_spacing << " m"
    << "\nphysics_dt: " << e.physics_dt << " s\ndecimation: " << e.decimation << " (control step "
    << e.controlDt() << " s)\nepisode_length_s: " << e.episode_length_s << " s (max_episode_length "
    << e.maxEpisodeLength() << ")\ndof_names: [";
  for (std::size_t i = 0; i < e.dof_names.size(); ++i) {
    s << (i ? ", " : "") << e.dof_names[i];
  }
  s << "]\nseed: " << e.seed << "\nnum_threads: " << e.num_threads << " (resolved "
    << e.resolvedThreads() << ")\ndrive_gain: " << e.drive_gain
    << " N m s/rad\neffort_limit: " << e.effort_limit
    << " N m\nsolver_iterations: " << e.solver_iterations << "\ntask: " << p.task
    << "\nreward: " << p.reward << "\nmode: " << modeName(p.mode)
    << "\nreal_time_factor: " << p.real_time_factor << "\naction_timeout: " << p.action_timeout
    << " s\npublish_clock: " << std::boolalpha << p.publish_clock << "\ntf_envs: " << p.tf_envs
    << "\ntf_rate: " << p.tf_rate << " Hz\nmarkers: " << p.markers;
  return s.str();
}

}  // namespace jetbot_rl
