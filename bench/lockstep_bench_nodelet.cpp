// jetbot_rl/LockstepBenchNodelet: jetbot_rl_ros_bench in a nodelet manager beside
// jetbot_rl/EnvNodelet (private parameters env_node, num_envs, steps); prints the same figures.
#include <pluginlib/class_list_macros.hpp>

#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/thread_nodelet.h"
#include "lockstep_bench.h"

namespace jetbot_rl {

class LockstepBenchNodelet : public ThreadNodelet {
  void onInit() override {
    const std::optional<LockstepBenchParams> params =
        loadParams<LockstepBenchParams>(getPrivateNodeHandle());
    if (!params) return;
    LockstepBenchOptions options;
    options.params = *params;
    options.answer_inline = false;  // see LockstepBenchOptions::answer_inline
    start([this, options](const std::atomic<bool>&) {
      ros::NodeHandle nh = getNodeHandle();
      return runLockstepBench(nh, options);
    });
  }
};

}  // namespace jetbot_rl

PLUGINLIB_EXPORT_CLASS(jetbot_rl::LockstepBenchNodelet, nodelet::Nodelet)
