#pragma once

#include <ros/time.h>

#include <cstdint>

#include "jetbot_rl/EnvSpec.h"
#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/env/step_result.h"

namespace jetbot_rl {

/// Copies `result` of a batch of `spec` into `msg` (the images its image_kinds names), reusing
/// the capacity of its arrays (no allocation once warm). `stamp`: the state's simulation time [s].
void toMsg(const StepResult& result, const BatchSpec& spec, const ros::Time& stamp, EnvStep& msg);
/// Copies `msg` into `result` (divergences are not carried by the message); Error naming the
/// field when its sizes do not fit `spec`.
void fromMsg(const EnvStep& msg, const BatchSpec& spec, StepResult& result);

/// The EnvSpec message of `spec`.
EnvSpec toMsg(const BatchSpec& spec);
/// The BatchSpec of `msg`; Error naming the field when it is inconsistent.
BatchSpec fromMsg(const EnvSpec& msg);

}  // namespace jetbot_rl
