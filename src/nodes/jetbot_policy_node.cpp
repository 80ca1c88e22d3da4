// jetbot_policy_node: drives a jetbot_env node with a trained policy's mean action.
#include <ros/init.h>

#include "jetbot_rl/ppo/ros/policy_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_policy", ros::init_options::NoSigintHandler);
  return jetbot_rl::ppo::runPolicyNode();
}
