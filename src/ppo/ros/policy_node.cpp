#include "jetbot_rl/ppo/ros/policy_node.h"

#include <ros/console.h>
#include <ros/node_handle.h>
#include <std_msgs/Float32.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>

#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/ppo/episode_tracker.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ros/policy_params.h"
#include "jetbot_rl/ros/client/connect_envs.h"
#include "jetbot_rl/ros/client/ros_vec_env.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/stop_signal.h"

namespace jetbot_rl {
namespace ppo {

int runPolicyNode() {
  const std::atomic<bool>& stop = installStopSignalHandlers();
  const int code = runPolicy(ros::NodeHandle(), ros::NodeHandle("~"), stop);
  ros::shutdown();
  return code;
}

int runPolicy(ros::NodeHandle nh, ros::NodeHandle pnh, const std::atomic<bool>& stop) {
  ppo::setTorchThreads(1);
  const std::optional<PolicyParams> loaded = loadPolicyParams(pnh);
  if (!loaded) return 1;
  const PolicyParams& params = *loaded;
  std::unique_ptr<Policy> policy;
  try {
    policy = std::make_unique<Policy>(params.checkpoint);
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  ROS_INFO("policy from iteration %lld (%lld env steps), best mean reward per step %.4f",
           static_cast<long long>(policy->meta().iteration),
           static_cast<long long>(policy->meta().env_steps), policy->meta().best_reward);
  ros::Publisher return_pub = pnh.advertise<std_msgs::Float32>("episode_return", 100);
  int code = 0;
  try {
    // One RosVecEnv per node, each with an observer of every EnvStep it receives (realtime
    // mode may deliver several per step): the episode returns are counted from them.
    std::int64_t episodes = 0;
    std::vector<float> actions;  // the targets last published
    std::string action_names;    // "name, name", from the spec
    // The batch's envs whose episode ended since the last step (realtime mode may deliver several
    // EnvSteps per step): their memory starts over.
    std::vector<std::uint32_t> ended_envs;
    std::uint32_t offset = 0;  // of the part's first env in the batch
    std::vector<std::unique_ptr<VecEnv>> parts;
    std::vector<std::unique_ptr<EpisodeTracker>> trackers;
    for (const std::string& name : params.env_nodes.env_nodes) {
      auto part = std::make_unique<RosVecEnv>(name, params.mode == EnvMode::kLockstep,
                                              params.env_nodes.step_timeout, &stop, nh);
      trackers.push_back(std::make_unique<EpisodeTracker>(part->spec().num_envs));
      part->setObserver([&, tracker = trackers.back().get(), name, offset](const EnvStep& msg) {
        for (std::uint32_t id : msg.reset_env_ids) ended_envs.push_back(offset + id);
        StepResult rewards_only;
        rewards_only.rewards = msg.rewards;
        rewards_only.reset_env_ids = msg.reset_env_ids;
        const std::vector<double>& ended = tracker->add(rewards_only);
        for (double r : ended) {
          std_msgs::Float32 out;
          out.data = static_cast<float>(r);
          return_pub.publish(out);
        }
        if (ended.empty()) return;
        episodes += static_cast<std::int64_t>(ended.size());
        ROS_INFO(
            "%s step %llu: %zu episode(s) ended, mean return %.3f (%lld episodes so far); "
            "actions of env 0: [%.2f, %.2f] (%s)",
            name.c_str(), static_cast<unsigned long long>(msg.step), ended.size(),
            std::accumulate(ended.begin(), ended.end(), 0.0) / ended.size(),
            static_cast<long long>(episodes), actions.size() > 1 ? actions[0] : 0.0f,
            actions.size() > 1 ? actions[1] : 0.0f, action_names.c_str());
      });
      offset += static_cast<std::uint32_t>(part->spec().num_envs);
      parts.push_back(std::move(part));
    }
    std::unique_ptr<VecEnv> env =
        parts.size() == 1
            ? std::move(parts[0])
            : std::make_unique<MultiVecEnv>(std::move(parts), params.env_nodes.env_nodes);
    const BatchSpec& info = env->spec();
    for (const std::string& warning : policy->fitTo(info)) ROS_WARN("%s", warning.c_str());
    for (const std::string& n : info.action_names) {
      action_names += (action_names.empty() ? "" : ", ") + n;
    }

    const StepResult* batch = &env->reset(params.reset_seed);
    ROS_INFO("driving %d env(s) with the mean action (%s mode)%s", info.num_envs,
             enumName(params.mode).c_str(),
             policy->hasMemory() ? "; the policy's memory starts over with each episode" : "");
    ended_envs.clear();
    for (std::int64_t k = 0; params.steps == 0 || k < params.steps; ++k) {
      policy->act(batch->observations, batch->images.rgb, info.num_envs, actions);
      batch = &env->step(actions);
      policy->resetMemory(ended_envs);
      ended_envs.clear();
    }
    ROS_INFO("drove %d steps; %lld episodes ended", params.steps, static_cast<long long>(episodes));
  } catch (const Interrupted&) {
    ROS_INFO("stopped");
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    code = 1;
  }
  return code;
}

}  // namespace ppo
}  // namespace jetbot_rl
