// jetbot_ppo_trainer: trains a PPO policy against a jetbot_env node in lockstep mode.
#include <ros/init.h>

#include "jetbot_rl/ppo/ros/trainer_node.h"

int main(int argc, char** argv) {
  // SIGINT is handled by the node: it saves a checkpoint before exiting.
  ros::init(argc, argv, "jetbot_ppo_trainer", ros::init_options::NoSigintHandler);
  return jetbot_rl::ppo::runTrainerNode();
}
