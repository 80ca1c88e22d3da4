#include "jetbot_rl/ppo/ros/trainer_node.h"

#include <ros/console.h>
#include <ros/node_handle.h>
#include <std_msgs/Float32MultiArray.h>

#include <memory>
#include <sstream>

#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/env/local_vec_env.h"
#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/ppo/freed_memory.h"
#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ros/trainer_params.h"
#include "jetbot_rl/ppo/runner.h"
#include "jetbot_rl/ros/client/connect_envs.h"
#include "jetbot_rl/ros/common/publication_flush.h"
#include "jetbot_rl/ros/common/robot_description.h"
#include "jetbot_rl/ros/common/stop_signal.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// The env's spec as config.yaml lines, each key prefixed "env_".
std::string describeSpec(const BatchSpec& spec) {
  std::istringstream lines(fieldsToYaml(spec));
  std::string s = "# environment (from its spec)\n";
  for (std::string line; std::getline(lines, line);) s += "env_" + line + "\n";
  return s;
}

std_msgs::Float32MultiArray statsMessage(const IterationStats& s) {
  std_msgs::Float32MultiArray msg;
  const std::vector<double> values = statsValues(s);
  std_msgs::MultiArrayDimension dim;
  dim.label = csvHeader(s.obs_names);  // the names of data[i], comma-separated
  dim.size = static_cast<std::uint32_t>(values.size());
  dim.stride = dim.size;
  msg.layout.dim.push_back(dim);
  msg.data.assign(values.begin(), values.end());
  return msg;
}

/// The env of the parameters under ~env_config[/part] (those of jetbot_env_node), built here.
std::unique_ptr<BatchedEnv> makeLocalEnv(const RobotModelConstPtr& robot,
                                         const ros::NodeHandle& pnh, const std::string& part) {
  const std::string ns = part.empty() ? "env_config" : "env_config/" + part;
  const ros::NodeHandle env_pnh(pnh, ns);
  try {
    const EnvSetup setup = readParams<EnvSetup>(env_pnh);
    echoParams(env_pnh, describeFields(setup));
    return makeEnv(robot, setup);
  } catch (const ConfigError& e) {
    throw ConfigError(ns + ": " + e.what());  // which part's parameter, among several
  }
}

/// The env the trainer trains on: env nodes, or one built in this process from ~env_config (one
/// part per name of env_nodes when there are several).
std::unique_ptr<VecEnv> makeTrainingEnv(const TrainerParams& params, const ros::NodeHandle& nh,
                                        const ros::NodeHandle& pnh, const std::atomic<bool>& stop) {
  if (!params.env_in_process) {
    return connectEnvs(params.env_nodes.env_nodes, true, params.env_nodes.step_timeout, &stop, nh);
  }
  const RobotModelConstPtr robot = loadRobotDescription(nh);
  const std::vector<std::string>& names = params.env_nodes.env_nodes;
  // One part: ~env_config itself; several (a mix of task configs): ~env_config/NAME each, as
  // the env nodes of those names would read them, stepped as one batch in list order.
  if (names.size() == 1) return std::make_unique<LocalVecEnv>(makeLocalEnv(robot, pnh, ""));
  std::vector<std::unique_ptr<VecEnv>> parts;
  for (const std::string& name : names) {
    parts.push_back(std::make_unique<LocalVecEnv>(makeLocalEnv(robot, pnh, name)));
  }
  return std::make_unique<MultiVecEnv>(std::move(parts), names);
}

}  // namespace

int runTrainerNode() {
  const std::atomic<bool>& stop = installStopSignalHandlers();
  const int code = runTrainer(ros::NodeHandle(), ros::NodeHandle("~"), stop);
  ros::shutdown();
  return code;
}

int runTrainer(ros::NodeHandle nh, ros::NodeHandle pnh, const std::atomic<bool>& stop) {
  const std::optional<TrainerConfig> config = loadTrainerConfig(pnh);
  if (!config) return 1;
  const TrainerParams& params = config->trainer;
  const PpoConfig& ppo = config->ppo;
  ppo::setTorchThreads(params.torch_threads);
  // The update's tensors come and go every iteration: kept, their pages are not faulted in anew.
  const std::string heap = ppo::keepFreedMemory();
  if (!heap.empty()) ROS_WARN("freed memory goes back to the system: %s", heap.c_str());

  // Latched: a late subscriber (a test, rqt_plot started later) still gets the newest row.
  ros::Publisher stats_pub =
      pnh.advertise<std_msgs::Float32MultiArray>("training_stats", 10, /*latch=*/true);
  int code = 0;
  try {
    const std::unique_ptr<VecEnv> env = makeTrainingEnv(params, nh, pnh, stop);
    const BatchSpec& spec = env->spec();
    std::ostringstream where;
    if (params.env_in_process) {
      where << "in this process";
    } else {
      writeValue(where, params.env_nodes.env_nodes);
    }
    ROS_INFO("environment %s: %d envs, task %s, obs_dim %d, action_dim %d, control step %.4f s",
             where.str().c_str(), spec.num_envs, spec.task.c_str(), spec.obs_dim, spec.action_dim,
             spec.control_dt);

    RunnerOptions options = params.run;
    options.extra_config = "# trainer\n" + fieldsToYaml(params) + describeSpec(spec);
    OnPolicyRunner runner(*env, ppo, options);
    runner.setLogger([](const std::string& line) { ROS_INFO_STREAM(line); });
    runner.setIterationCallback(
        [&stats_pub](const IterationStats& s) { stats_pub.publish(statsMessage(s)); });
    ROS_INFO("training for %lld iterations of %d steps x %d envs into %s",
             static_cast<long long>(options.iterations), runner.config().num_steps_per_env,
             spec.num_envs, options.run_dir.c_str());

    const TrainingSummary summary = runner.learn();
    ROS_INFO_STREAM("final figures:\n" << describeSummary(summary));
    if (!summary.error.empty()) {
      const std::string saved =
          summary.iterations == 0
              ? std::string("no iteration completed: the initial model is saved in ")
              : "iteration " + std::to_string(summary.iterations) +
                    ", the last completed, is saved in ";
      ROS_FATAL("%s: training failed: %s (%s%s)", pnh.getNamespace().c_str(), summary.error.c_str(),
                saved.c_str(), options.run_dir.c_str());
      code = 1;
    }
    if (code == 0 && params.end_launch) endParentLaunch(stop);
  } catch (const Interrupted& e) {
    ROS_WARN("stopped before training started: %s", e.what());
  } catch (const ConfigError& e) {
    logParamError(pnh, e);
    code = 1;
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    code = 1;
  }
  // The last ~training_stats must leave before the publisher goes (a waiting test, rqt_plot).
  flushPublications(0.5);
  return code;
}

}  // namespace ppo
}  // namespace jetbot_rl
