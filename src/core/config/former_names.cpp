#include "jetbot_rl/config/former_names.h"

namespace jetbot_rl {

const std::vector<FormerName>& formerNames() {
  static const std::vector<FormerName> names{
      {"env", "env_nodes"},
      {"envs", "env_nodes"},
      {"reward", "reward_variant"},
      {"robot_envs", "robot_view_envs"},
      {"--envs", "--num-envs"},
      {"--nodes", "--env-nodes"},
      // The policy node's robot mode is the deploy node now.
      {"robot", "env_nodes",
       "the robot mode is the node jetbot_deploy_node now (launch/navigate.launch, "
       "launch/deploy.launch): run it instead of jetbot_policy_node"},
      // The deploy node takes what the policy was trained with from its checkpoint.
      {"control_rate", "checkpoint", "comes from the checkpoint now (1 / its control step)"},
      {"wheel_velocity_limit", "checkpoint", "comes from the checkpoint now (its action bounds)"},
      {"twist_limits", "checkpoint", "comes from the checkpoint now (its action bounds)"},
      {"policy_actions", "checkpoint", "comes from the checkpoint now (its action names)"},
      {"nav/beams", "checkpoint", "comes from the checkpoint now (its scan_beam_angles)"},
      {"scan_beams", "checkpoint", "comes from the checkpoint now (its scan_beam_angles)"},
      {"scan_angles", "checkpoint", "comes from the checkpoint now (its scan_beam_angles)"},
      {"scan_range", "checkpoint", "comes from the checkpoint now (its scan_range)"},
      {"nav/goal_radius", "xy_goal_tolerance"},
      {"goal_radius", "xy_goal_tolerance"},
  };
  return names;
}

}  // namespace jetbot_rl
