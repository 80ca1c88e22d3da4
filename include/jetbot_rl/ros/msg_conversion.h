#pragma once

#include <ros/time.h>

#include <cstdint>

#include "jetbot_rl/EnvSpec.h"
#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/// Copies `result` into `msg`, reusing the capacity of its arrays (no allocation once warm).
/// `stamp` is the simulation time of the state [s]; `step` the EnvStep.step counter.
void fillEnvStep(const StepResult& result, int num_envs, int obs_dim, std::uint64_t step,
                 const ros::Time& stamp, EnvStep& msg);

/// The EnvSpec of `env`: sizes, action bounds [rad/s], control step [s], names.
EnvSpec makeEnvSpec(const BatchedEnv& env);

}  // namespace jetbot_rl
