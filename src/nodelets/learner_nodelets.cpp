// The learners as nodelets: jetbot_rl/TrainerNodelet and PolicyNodelet run what their programs
// run, in a thread of their own, on the nodelet's node handles. In a manager with
// jetbot_rl/EnvNodelet they pass messages by shared pointer (no serialisation, no TCP): the
// in-process path for small batches. A library of its own: libtorch is loaded only with them.
#include <pluginlib/class_list_macros.hpp>

#include "jetbot_rl/ppo/ros/policy_node.h"
#include "jetbot_rl/ppo/ros/trainer_node.h"
#include "jetbot_rl/ros/common/thread_nodelet.h"

namespace jetbot_rl {

class TrainerNodelet : public ThreadNodelet {
  void onInit() override {
    start([this](const std::atomic<bool>& stop) {
      return ppo::runTrainer(getNodeHandle(), getPrivateNodeHandle(), stop);
    });
  }
};

class PolicyNodelet : public ThreadNodelet {
  void onInit() override {
    start([this](const std::atomic<bool>& stop) {
      return ppo::runPolicy(getNodeHandle(), getPrivateNodeHandle(), stop);
    });
  }
};

}  // namespace jetbot_rl

PLUGINLIB_EXPORT_CLASS(jetbot_rl::TrainerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(jetbot_rl::PolicyNodelet, nodelet::Nodelet)
