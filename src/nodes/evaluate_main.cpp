// jetbot_rl_evaluate --checkpoint PATH (a file or a run directory: its best.pt) [--task NAME]
// [--config YAML ...] [--num-envs N] [--steps S] [--seed S] [--urdf PATH]: plays a trained
// policy's mean action in-process on envs configured by the YAML files (EnvSetup: the env node's
// parameter names: task, reward_variant, randomisation ranges, ...), and prints the mean reward
// per step over every env step. For evaluating a policy on perturbed physics (docs/sim_to_real.md).
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "jetbot_rl/command_line.h"
#include "jetbot_rl/ppo/policy.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  EnvProgramOptions env_options;
  env_options.num_envs = 64;
  env_options.steps = 600;
  env_options.threads = 1;
  env_options.urdf = JETBOT_RL_DEFAULT_URDF;
  std::string checkpoint, task;
  long long seed = 1000;
  std::string error;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--checkpoint") {
      checkpoint = value;
    } else if (option == "--task") {
      task = value;
    } else if (option == "--seed") {
      parseWholeNumber(option, value, 0, std::numeric_limits<long long>::max(), seed, error);
    } else {
      return env_options.take(option, value, error);
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
        "[--seed S] %s\n",
        error.c_str(), EnvProgramOptions::usage());
    return 2;
  }
  try {
    EnvSetup setup = env_options.setup();
    if (!task.empty()) fieldsFromYaml("task: " + task, setup);
    setup.env.seed = static_cast<std::uint64_t>(seed);
    const std::unique_ptr<BatchedEnv> batch =
        makeEnv(RobotModel::fromUrdfFile(env_options.urdf), setup);
    BatchedEnv& env = *batch;
    const int envs = env.numEnvs(), steps = env_options.steps;
    if (std::filesystem::is_directory(checkpoint)) checkpoint += "/checkpoints/best.pt";
    ppo::Policy policy(checkpoint);
    policy.setActionLimits(env.actionLow(), env.actionHigh());
    std::vector<float> actions;
    double reward_sum = 0.0;
    for (int s = 0; s < steps; ++s) {
      policy.act(env.state().observations, envs, actions);
      for (float r : env.step(actions).rewards) reward_sum += r;
    }
    std::printf("task=%s envs=%d steps=%d\n", env.task().name().c_str(), envs, steps);
    std::printf("mean_reward_per_step=%.4f\n", reward_sum / (static_cast<double>(steps) * envs));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_evaluate: %s\n", e.what());
    return 1;
  }
  return 0;
}
