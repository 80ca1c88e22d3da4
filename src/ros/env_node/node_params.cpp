#include "jetbot_rl/ros/env_node/node_params.h"

#include <ros/names.h>

namespace jetbot_rl {

void checkFieldRules(const NodeParams& p) {
  checkFieldRules(p.setup);
  if (!p.env_prefix && robotViewEnvs(p) != 1) {
    throwInvalid("env_prefix", "false",
                 "drops the env_0/ prefix of a single robot env: needs robot_view_envs 1, got " +
                     std::to_string(p.robot_view_envs) + " with num_envs " +
                     std::to_string(p.setup.env.num_envs));
  }
  std::string why;
  if (!p.robot_prefix.empty() && (p.robot_prefix.front() == '/' || p.robot_prefix.front() == '~' ||
                                  !ros::names::validate(p.robot_prefix, why))) {
    throwInvalid("robot_prefix", "'" + p.robot_prefix + "'",
                 "must be empty or a relative ROS name (e.g. jetbot_env_1/)" +
                     (why.empty() ? std::string() : ": " + why));
  }
}

}  // namespace jetbot_rl
