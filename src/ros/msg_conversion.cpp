#include "jetbot_rl/ros/msg_conversion.h"

namespace jetbot_rl {

void fillEnvStep(const StepResult& r, int num_envs, int obs_dim, std::uint64_t step,
                 const ros::Time& stamp, EnvStep& msg) {
  msg.header.stamp = stamp;
  msg.step = step;
  msg.num_envs = static_cast<std::uint32_t>(num_envs);
  msg.obs_dim = static_cast<std::uint32_t>(obs_dim);
  // assign() of contiguous ranges: one memcpy each, capacity kept between steps.
  msg.observations.assign(r.observations.begin(), r.observations.end());
  msg.rewards.assign(r.rewards.begin(), r.rewards.end());
  msg.terminated.assign(r.terminated.begin(), r.terminated.end());
  msg.truncated.assign(r.truncated.begin(), r.truncated.end());
  msg.episode_steps.assign(r.episode_steps.begin(), r.episode_steps.end());
  msg.reset_env_ids.assign(r.reset_env_ids.begin(), r.reset_env_ids.end());
  msg.final_observations.assign(r.final_observations.begin(), r.final_observations.end());
}

EnvSpec makeEnvSpec(const BatchedEnv& env) {
  EnvSpec spec;
  spec.num_envs = static_cast<std::uint32_t>(env.numEnvs());
  spec.obs_dim = static_cast<std::uint32_t>(env.obsDim());
  spec.action_dim = static_cast<std::uint32_t>(env.actionDim());
  spec.action_low = env.actionLow();
  spec.action_high = env.actionHigh();
  spec.control_dt = env.controlDt();
  spec.max_episode_length = static_cast<std::uint32_t>(env.maxEpisodeLength());
  spec.task = env.task().name();
  spec.observation_names = env.task().observationNames();
  spec.action_names = env.config().dof_names;
  return spec;
}

}  // namespace jetbot_rl
