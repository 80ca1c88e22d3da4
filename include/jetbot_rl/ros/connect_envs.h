#pragma once

#include <ros/node_handle.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/vec_env.h"

namespace jetbot_rl {

/// The env nodes `names` (relative names resolve in `parent`'s namespace) as one VecEnv: a
/// RosVecEnv for one name, a MultiVecEnv of them for several (node k reset with seed + k x 2^32).
/// Throws Error naming the node that does not answer within `timeout` [s], ConfigError naming the
/// node and field whose spec disagrees.
std::unique_ptr<VecEnv> connectEnvs(const std::vector<std::string>& names, bool lockstep,
                                    double timeout, const std::atomic<bool>* stop,
                                    const ros::NodeHandle& parent = ros::NodeHandle());

}  // namespace jetbot_rl
