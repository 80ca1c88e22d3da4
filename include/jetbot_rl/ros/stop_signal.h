#pragma once

#include <atomic>

namespace jetbot_rl {

/// Installs SIGINT and SIGTERM handlers that only set the returned flag, so that a node can save
/// and publish what it must before it ends: roscpp's own SIGINT handler shuts ROS down at once
/// (a message published after that never leaves), and SIGTERM's default ends the process. Use
/// with ros::init_options::NoSigintHandler.
const std::atomic<bool>& installStopSignalHandlers();

}  // namespace jetbot_rl
