// jetbot_rl/EnvNodelet: jetbot_env_node's EnvNode in a nodelet manager, so that a learner nodelet
// in the same manager exchanges WheelTargets and EnvStep with it by shared pointer.
#include <nodelet/nodelet.h>

#include <memory>
#include <pluginlib/class_list_macros.hpp>

#include "jetbot_rl/ros/env_node/env_node.h"

namespace jetbot_rl {

class EnvNodelet : public nodelet::Nodelet {
 public:
  ~EnvNodelet() override {
    if (node_) node_->shutdown(0.5);
  }

 private:
  void onInit() override {
    // The same parameters, topics and services as the node (its private namespace is the
    // nodelet's name); timers run on the manager's threads.
    node_ = makeEnvNode(getNodeHandle(), getPrivateNodeHandle());
    if (!node_) throw nodelet::Exception(getName() + ": cannot start (see the FATAL above)");
  }

  std::unique_ptr<EnvNode> node_;
};

}  // namespace jetbot_rl

PLUGINLIB_EXPORT_CLASS(jetbot_rl::EnvNodelet, nodelet::Nodelet)
