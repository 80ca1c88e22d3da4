#pragma once

#include <ros/callback_queue.h>

#include <atomic>

namespace jetbot_rl {

/// Installs SIGINT and SIGTERM handlers that only set the returned flag, so that a node can save
/// and publish what it must before it ends: roscpp's own SIGINT handler shuts ROS down at once
/// (a message published after that never leaves), and SIGTERM's default ends the process. Use
/// with ros::init_options::NoSigintHandler.
const std::atomic<bool>& installStopSignalHandlers();

/// Returns once `stop` is set or ROS shuts down. The signal handler only sets `stop`, which
/// nothing can wait on: it is looked at every 0.1 s, meanwhile serving `queue`'s callbacks
/// (timers, say) when one is given, else sleeping (a spinner serves the callbacks).
void waitForStop(const std::atomic<bool>& stop, ros::CallbackQueue* queue = nullptr);

/// When this process was started by roslaunch, ends that launch as Ctrl-C would (SIGINT to it)
/// and waits up to 10 s for roslaunch's own SIGINT to set `stop`: a node that roslaunch sees
/// exit on its own first is announced, if required, as "REQUIRED process has died". Returns
/// false (and does nothing) when the parent is not roslaunch.
bool endParentLaunch(const std::atomic<bool>& stop);

}  // namespace jetbot_rl
