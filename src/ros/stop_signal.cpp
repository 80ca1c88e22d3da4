#include "jetbot_rl/ros/stop_signal.h"

#include <csignal>

namespace jetbot_rl {
namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) { g_stop.store(true); }

}  // namespace

const std::atomic<bool>& installStopSignalHandlers() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  return g_stop;
}

}  // namespace jetbot_rl
