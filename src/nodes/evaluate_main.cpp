// jetbot_rl_evaluate --checkpoint PATH (a file or a run directory: its best.pt) [--task NAME]
// [--config YAML ...] [--envs N] [--steps S] [--seed S]
//   [--urdf PATH]: plays a trained policy's mean action in-process on envs configured by the
// YAML files (the env node's parameter names: task, reward, randomisation ranges, ...), and
// prints the mean reward per step over every env step. For evaluating a policy on perturbed
// physics (README "Sim-to-real").
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "jetbot_rl/batched_env.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {

/// The env's configuration as the evaluator reads it: the env node's names for these fields.
struct EvaluationConfig {
  EnvConfig env;
  TaskConfig task;
};

template <typename C, typename V>
IfConfig<C, EvaluationConfig> visitFields(C& c, V&& v) {
  visitFields(c.env, v);
  visitFields(c.task, v);
}

}  // namespace jetbot_rl

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  std::string checkpoint, urdf = JETBOT_RL_DEFAULT_URDF;
  std::vector<std::string> configs;
  std::string task;
  long long envs = 64, steps = 600, seed = 1000;
  std::string error;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--checkpoint") {
      checkpoint = value;
    } else if (option == "--task") {
      task = value;
    } else if (option == "--config") {
      configs.push_back(value);
    } else if (option == "--urdf") {
      urdf = value;
    } else if (option == "--envs") {
      parseWholeNumber(option, value, 1, 100000, envs, error);
    } else if (option == "--steps") {
      parseWholeNumber(option, value, 1, 100000000, steps, error);
    } else if (option == "--seed") {
      parseWholeNumber(option, value, 0, std::numeric_limits<long long>::max(), seed, error);
    } else {
      return false;
    }
    return true;
  };
  if (parseOptions(argc, argv, take, error) && checkpoint.empty()) {
    error = "--checkpoint is required";
  }
  if (!error.empty()) {
    std::fprintf(
        stderr,
        "jetbot_rl_evaluate: %s\nusage: jetbot_rl_evaluate --checkpoint PATH [--task NAME] "
        "[--config YAML ...] [--envs N] [--steps S] [--seed S] [--urdf PATH]\n",
        error.c_str());
    return 2;
  }
  try {
    EvaluationConfig config;
    for (const std::string& path : configs) {
      std::ifstream file(path);
      if (!file) throw Error("cannot read " + path);
      std::ostringstream text;
      text << file.rdbuf();
      fieldsFromYaml(text.str(), config);
    }
    if (!task.empty()) fieldsFromYaml("task: " + task, config);
    config.env.num_envs = static_cast<int>(envs);
    config.env.num_threads = 1;
    config.env.seed = static_cast<std::uint64_t>(seed);
    config.env.validate();
    BatchedEnv env(RobotModel::fromUrdfFile(urdf), config.env, makeTask(config.task));
    if (std::filesystem::is_directory(checkpoint)) checkpoint += "/checkpoints/best.pt";
    ppo::Policy policy(checkpoint);
    policy.setActionLimits(env.actionLow(), env.actionHigh());
    std::vector<float> actions;
    double reward_sum = 0.0;
    for (int s = 0; s < steps; ++s) {
      policy.act(env.state().observations, static_cast<int>(envs), actions);
      for (float r : env.step(actions).rewards) reward_sum += r;
    }
    std::printf("task=%s envs=%lld steps=%lld\n", env.task().name().c_str(), envs, steps);
    std::printf("mean_reward_per_step=%.4f\n", reward_sum / (static_cast<double>(steps) * envs));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_evaluate: %s\n", e.what());
    return 1;
  }
  return 0;
}
