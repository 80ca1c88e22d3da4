#pragma once

#include <ros/node_handle.h>

#include <atomic>

namespace jetbot_rl {
namespace ppo {

/**
 * Runs jetbot_policy_node after ros::init(..., NoSigintHandler): loads ~checkpoint, connects to
 * the env (~env, in ~mode lockstep or realtime), resets it and drives it with the policy's mean
 * action, publishing the return of every finished episode on ~episode_return
 * (std_msgs/Float32). Ends after ~steps control steps (0: until Ctrl-C). Returns the exit code;
 * a bad parameter or checkpoint is ROS_FATAL and returns 1.
 */
int runPolicyNode();

/// The player on node handles `nh` (env names and topics resolve in its namespace) and `pnh`
/// (its parameters), until done or `stop`. Returns the exit code; never shuts ROS down.
int runPolicy(ros::NodeHandle nh, ros::NodeHandle pnh, const std::atomic<bool>& stop);

}  // namespace ppo
}  // namespace jetbot_rl
