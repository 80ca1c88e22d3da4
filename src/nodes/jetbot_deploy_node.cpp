// jetbot_deploy_node: a trained policy driving a robot (odometry, scan and goals in, cmd_vel out).
#include <ros/init.h>

#include "jetbot_rl/ros/deploy/deploy_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_deploy", ros::init_options::NoSigintHandler);
  return jetbot_rl::runDeployNode();
}
