// jetbot_depth_scan: a robot's depth camera turned into the LaserScan training made of the
// simulated camera's depth (scan/source camera_depth), for the deploy node's scan input.
#include <ros/init.h>

#include "jetbot_rl/ros/deploy/depth_scan_publisher.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_depth_scan");
  return jetbot_rl::runDepthScanNode();
}
