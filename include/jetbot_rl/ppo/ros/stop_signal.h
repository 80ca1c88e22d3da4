#pragma once

#include <atomic>

namespace jetbot_rl {
namespace ppo {

/// Installs SIGINT and SIGTERM handlers that set the returned flag (the nodes then save and exit
/// instead of dying mid-step). Use with ros::init_options::NoSigintHandler.
const std::atomic<bool>& installStopSignalHandlers();

}  // namespace ppo
}  // namespace jetbot_rl
