// jetbot_env_node: the batched Jetbot environment on ROS topics and services.
#include <ros/init.h>

#include "jetbot_rl/ros/env_node/env_node.h"

int main(int argc, char** argv) {
  // SIGINT and SIGTERM are handled by the node: it sends its last markers before exiting.
  ros::init(argc, argv, "jetbot_env", ros::init_options::NoSigintHandler);
  return jetbot_rl::runEnvNode();
}
