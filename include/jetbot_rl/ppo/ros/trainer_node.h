#pragma once

#include <ros/node_handle.h>

#include <atomic>

namespace jetbot_rl {
namespace ppo {

/**
 * Runs jetbot_ppo_trainer after ros::init(..., NoSigintHandler): reads and echoes the
 * parameters, connects to the env, trains (progress lines, progress.csv, checkpoints,
 * ~training_stats) and prints the final figures. SIGINT/SIGTERM save a checkpoint and end the
 * run. Returns the exit code: 0 when completed or interrupted, 1 for a bad parameter (ROS_FATAL)
 * or a failed run.
 */
int runTrainerNode();

/// The trainer on node handles `nh` (its namespace: env names resolve in it) and `pnh` (its
/// parameters), until done or `stop` (jetbot_ppo_trainer with signals, the nodelet with its
/// unloading). Returns the exit code; never shuts ROS down.
int runTrainer(ros::NodeHandle nh, ros::NodeHandle pnh, const std::atomic<bool>& stop);

}  // namespace ppo
}  // namespace jetbot_rl
