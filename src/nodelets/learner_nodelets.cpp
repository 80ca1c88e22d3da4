// The learners as nodelets: jetbot_rl/TrainerNodelet, PolicyNodelet and LockstepBenchNodelet run
// what their programs run, in a thread of their own, on the nodelet's node handles. In a
// manager with jetbot_rl/EnvNodelet they pass messages by shared pointer (no serialisation, no
// TCP): the in-process path for small batches.
#include <nodelet/nodelet.h>
#include <ros/console.h>

#include <atomic>
#include <functional>
#include <pluginlib/class_list_macros.hpp>
#include <thread>

#include "jetbot_rl/ppo/ros/policy_node.h"
#include "jetbot_rl/ppo/ros/trainer_node.h"
#include "jetbot_rl/ros/param_reader.h"
#include "lockstep_bench.h"

namespace jetbot_rl {

/// A nodelet whose work is one function run on its own thread until it returns or the nodelet
/// is unloaded (which sets the stop flag the function watches).
class ThreadNodelet : public nodelet::Nodelet {
 public:
  ~ThreadNodelet() override {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }

 protected:
  /// Starts `work` (returning an exit code, logged when not 0).
  void start(std::function<int(const std::atomic<bool>&)> work) {
    thread_ = std::thread([this, work = std::move(work)] {
      const int code = work(stop_);
      if (code != 0) NODELET_ERROR("%s ended with exit code %d", getName().c_str(), code);
    });
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

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

/// jetbot_rl_ros_bench in the manager: private parameters env_node (the env's name), num_envs
/// (its num_envs), steps; prints the same figures.
class LockstepBenchNodelet : public ThreadNodelet {
  void onInit() override {
    const ros::NodeHandle& pnh = getPrivateNodeHandle();
    LockstepBenchParams params;
    try {
      readFields(pnh, params);
      validateFields(params);
    } catch (const Error& e) {
      NODELET_FATAL("%s: parameter error: %s", pnh.getNamespace().c_str(), e.what());
      return;
    }
    NODELET_INFO_STREAM("parameters of " << pnh.getNamespace() << ":\n" << describeFields(params));
    LockstepBenchOptions options;
    options.env_ns = getNodeHandle().resolveName(params.env_node);
    options.envs = params.num_envs;
    options.steps = params.steps;
    options.answer_inline = false;  // see LockstepBenchOptions::answer_inline
    start([this, options](const std::atomic<bool>&) {
      ros::NodeHandle nh = getNodeHandle();
      return runLockstepBench(nh, options);
    });
  }
};

}  // namespace jetbot_rl

PLUGINLIB_EXPORT_CLASS(jetbot_rl::TrainerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(jetbot_rl::PolicyNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(jetbot_rl::LockstepBenchNodelet, nodelet::Nodelet)
