#pragma once

#include <ros/node_handle.h>

#include <atomic>

namespace jetbot_rl {

/// jetbot_deploy_node: installs the stop signal handlers, runs runDeploy() with the node's
/// handles and shuts ROS down. Returns the exit code.
int runDeployNode();

/**
 * Drives a robot with a trained policy until `stop` or ROS shutdown: reads DeployParams under
 * `pnh` (ROS_FATAL naming a bad one), loads the checkpoint, builds the observer of the task it
 * was trained on from its env spec (the task's own observation code) and runs a DeployDriver.
 * Returns the exit code (1 after a FATAL).
 */
int runDeploy(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::atomic<bool>& stop);

}  // namespace jetbot_rl
