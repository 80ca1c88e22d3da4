// jetbot_env_node: the batched Jetbot environment on ROS topics and services.
#include <ros/init.h>

#include "jetbot_rl/ros/env_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_env");
  return jetbot_rl::runEnvNode();
}
