#pragma once

#include <ros/node_handle.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/env/vec_env.h"
#include "jetbot_rl/ros/common/param_reader.h"

namespace jetbot_rl {

/// The env nodes a learner steps (jetbot_ppo_trainer, jetbot_policy_node): private parameters.
struct EnvNodesParams {
  /// The jetbot_env nodes whose envs form one batch, in order (one name or a list; relative
  /// names resolve in the node's namespace); node k is reset with seed + k x 2^32.
  std::vector<std::string> env_nodes{"jetbot_env"};
  double step_timeout = 10.0;  ///< Give up when an env does not answer within this [s, wall].
};

template <typename C, typename V>
IfConfig<C, EnvNodesParams> visitFields(C& c, V&& v) {
  v("env_nodes", c.env_nodes, GraphNames{},
    "The jetbot_env nodes whose envs form one batch, in list order (one name or a list; "
    "relative names resolve in this node's namespace); node k is reset with seed + k x 2^32.");
  v("step_timeout", c.step_timeout, positive("s, wall"),
    "Give up (save, exit 1) when an env node does not answer within this.");
}

/// The env nodes `names` (relative names resolve in `parent`'s namespace) as one VecEnv: a
/// RosVecEnv for one name, a MultiVecEnv of them for several (node k reset with seed + k x 2^32).
/// Throws Error naming the node that does not answer within `timeout` [s], ConfigError naming the
/// node and field whose spec disagrees.
std::unique_ptr<VecEnv> connectEnvs(const std::vector<std::string>& names, bool lockstep,
                                    double timeout, const std::atomic<bool>* stop,
                                    const ros::NodeHandle& parent = ros::NodeHandle());

}  // namespace jetbot_rl
