#include "jetbot_rl/ppo/ros/trainer_node.h"

#include <ros/console.h>
#include <ros/node_handle.h>
#include <std_msgs/Float32MultiArray.h>
#include <torch/utils.h>

#include <sstream>

#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/ros/ros_vec_env.h"
#include "jetbot_rl/ppo/ros/stop_signal.h"
#include "jetbot_rl/ppo/ros/trainer_params.h"
#include "jetbot_rl/ppo/runner.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string describeSpec(const EnvSpec& spec) {
  std::ostringstream s;
  s << "# environment (from ~spec)\nenv_num_envs: " << spec.num_envs
    << "\nenv_obs_dim: " << spec.obs_dim << "\nenv_action_dim: " << spec.action_dim
    << "\nenv_action_low: [";
  for (std::size_t i = 0; i < spec.action_low.size(); ++i) {
    s << (i ? ", " : "") << spec.action_low[i];
  }
  s << "]\nenv_action_high: [";
  for (std::size_t i = 0; i < spec.action_high.size(); ++i) {
    s << (i ? ", " : "") << spec.action_high[i];
  }
  s << "]\nenv_control_dt: " << spec.control_dt
    << "\nenv_max_episode_length: " << spec.max_episode_length << "\nenv_task: " << spec.task
    << "\n";
  return s.str();
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

}  // namespace

int runTrainerNode() {
  const std::atomic<bool>& stop = installStopSignalHandlers();
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  TrainerParams params;
  try {
    params = loadTrainerParams(pnh);
  } catch (const Error& e) {
    ROS_FATAL("%s: parameter error: %s", pnh.getNamespace().c_str(), e.what());
    ros::shutdown();
    return 1;
  }
  ROS_INFO_STREAM("parameters of " << pnh.getNamespace() << ":\n" << describeTrainerParams(params));
  torch::set_num_threads(params.torch_threads);

  // Latched: a late subscriber (a test, rqt_plot started later) still gets the newest row.
  ros::Publisher stats_pub =
      pnh.advertise<std_msgs::Float32MultiArray>("training_stats", 10, /*latch=*/true);
  int code = 0;
  try {
    RosVecEnv env(params.env, /*lockstep=*/true, params.step_timeout, &stop);
    const EnvSpec& spec = env.spec();
    ROS_INFO("environment %s: %u envs, task %s, obs_dim %u, action_dim %u, control step %.4f s",
             params.env.c_str(), spec.num_envs, spec.task.c_str(), spec.obs_dim, spec.action_dim,
             spec.control_dt);

    RunnerOptions options;
    options.iterations = params.iterations;
    options.run_dir = params.run_dir;
    options.resume = params.resume;
    options.save_interval = params.save_interval;
    options.target_reward = params.target_reward;
    options.obs_stats_from_step = params.obs_stats_from_step;
    options.extra_config =
        "# trainer\n" + describeTrainerParams(params, false) + describeSpec(spec);
    OnPolicyRunner runner(env, params.ppo, options);
    runner.setLogger([](const std::string& line) { ROS_INFO_STREAM(line); });
    runner.setIterationCallback(
        [&stats_pub](const IterationStats& s) { stats_pub.publish(statsMessage(s)); });
    ROS_INFO("training for %d iterations of %d steps x %u envs into %s", params.iterations,
             runner.config().num_steps_per_env, spec.num_envs, params.run_dir.c_str());

    const TrainingSummary summary = runner.learn();
    ROS_INFO_STREAM("final figures:\n" << describeSummary(summary));
    if (!summary.error.empty()) code = 1;
  } catch (const Interrupted& e) {
    ROS_WARN("stopped before training started: %s", e.what());
  } catch (const ConfigError& e) {
    ROS_FATAL("%s: parameter error: %s", pnh.getNamespace().c_str(), e.what());
    code = 1;
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    code = 1;
  }
  ros::shutdown();
  return code;
}

}  // namespace ppo
}  // namespace jetbot_rl
