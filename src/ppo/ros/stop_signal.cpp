#include "jetbot_rl/ppo/ros/stop_signal.h"

#include "jetbot_rl/ros/stop_signal.h"

namespace jetbot_rl {
namespace ppo {

const std::atomic<bool>& installStopSignalHandlers() {
  return jetbot_rl::installStopSignalHandlers();
}

}  // namespace ppo
}  // namespace jetbot_rl
