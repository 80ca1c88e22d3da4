#include "jetbot_rl/ros/node_params.h"

#include "jetbot_rl/ros/param_reader.h"

namespace jetbot_rl {

void validateNodeParams(const NodeParams& p) {
  validateFields(p);
  p.env.validate();  // the rules between EnvConfig's fields
  if (!p.env_prefix && robotEnvs(p) != 1) {
    throwInvalid("env_prefix", "false",
                 "drops the env_0/ prefix of a single robot env: needs robot_envs 1, got " +
                     std::to_string(p.robot_envs) + " with num_envs " +
                     std::to_string(p.env.num_envs));
  }
}

NodeParams loadNodeParams(const ros::NodeHandle& pnh) {
  NodeParams p;
  readFields(pnh, p);
  validateNodeParams(p);
  return p;
}

}  // namespace jetbot_rl
