#include "jetbot_rl/ros/env_node/state_output.h"

namespace jetbot_rl {
EnvStepOutput::EnvStepOutput(ros::NodeHandle& pnh, std::uint32_t queue_size,
                             CountedSubscriberQueues& queues)
    : pub_(advertiseCounted<EnvStep>(pnh, "env_step", queue_size, queues)) {}

void EnvStepOutput::send() {
  if (msg_) pub_.publish(msg_);
  msg_.reset();
}

bool SimRateGate::due(const ros::Time& stamp, bool reset) {
  if (sent_ && stamp == last_) {
    pending_ = pending_ || reset;
    return false;
  }
  if (!reset && !pending_ && sent_ && stamp - last_ < period_) return false;
  pending_ = false;
  last_ = stamp;
  sent_ = true;
  return true;
}

}  // namespace jetbot_rl
