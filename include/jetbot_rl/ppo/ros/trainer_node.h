#pragma once

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

}  // namespace ppo
}  // namespace jetbot_rl
