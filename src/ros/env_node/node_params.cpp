#include "jetbot_rl/ros/env_node/node_params.h"

namespace jetbot_rl {

void checkFieldRules(const NodeParams& p) {
  checkFieldRules(p.setup);
  if (!p.env_prefix && robotEnvs(p) != 1) {
    throwInvalid("env_prefix", "false",
                 "drops the env_0/ prefix of a single robot env: needs robot_envs 1, got " +
                     std::to_string(p.robot_envs) + " with num_envs " +
                     std::to_string(p.setup.env.num_envs));
  }
}

}  // namespace jetbot_rl
