// jetbot_rl_evaluate --checkpoint PATH (a file or a run directory: its best.pt) [--task NAME]
// [--config YAML ...] [--num-envs N] [--steps S] [--seed S] [--urdf PATH] [--episodes N]
// [--obs-from-step K]: plays a trained policy's mean action in-process on envs configured by the
// YAML files (EnvSetup: the env node's parameter names: task, reward_variant, randomisation
// ranges, ...), and prints the mean reward per step over every env step; with --obs-from-step the
// mean and mean absolute value of each observation the policy acted on at episode step K or later.
// For evaluating a policy on perturbed physics (docs/sim_to_real.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/ppo/policy.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  PolicyProgramOptions options;
  EnvProgramOptions& env_options = options.env;
  env_options.num_envs = 64;
  env_options.steps = 600;
  env_options.threads = 1;
  env_options.urdf = JETBOT_RL_DEFAULT_URDF;
  std::string task;
  int obs_from_step = -1;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--task") {
      task = value;
    } else if (option == "--obs-from-step") {
      parseWholeNumber(option, value, 0, 100000000, obs_from_step, error);
    } else {
      return false;
    }
    return true;
  };
  if (!options.parse(argc, argv, "jetbot_rl_evaluate", "[--task NAME] [--obs-from-step K]", take)) {
    return 2;
  }
  std::string checkpoint = options.checkpoint;
  const long long seed = options.seed;
  const int episodes = options.episodes;
  try {
    EnvSetup setup = env_options.setup();
    if (!task.empty()) fieldsFromYaml("task: " + task, setup);
    setup.env.seed = static_cast<std::uint64_t>(seed);
    const std::unique_ptr<BatchedEnv> batch = makeEnv(
        RobotModel::fromUrdfFile(env_options.urdf, EnvProgramOptions::packagePathResolver()),
        setup);
    BatchedEnv& env = *batch;
    const int envs = env.numEnvs(), steps = env_options.steps;
    if (std::filesystem::is_directory(checkpoint)) checkpoint += "/checkpoints/best.pt";
    ppo::Policy policy(checkpoint);
    for (const std::string& warning : policy.fitTo(env.spec())) {
      std::fprintf(stderr, "warning: %s\n", warning.c_str());
    }
    std::vector<float> actions;
    double reward_sum = 0.0;
    // With --episodes: the first ceil(N / envs) episodes of every env (a quota per env, so that
    // short episodes are not over-counted), the steps a cap.
    const int quota = episodes > 0 ? (episodes + envs - 1) / envs : 0;
    std::vector<int> done(envs, 0);
    std::int64_t outcome_count[3] = {0, 0, 0}, episode_steps = 0, counted = 0, full = 0;
    std::int64_t mover_hits = 0, robot_hits = 0;
    const int obs_dim = env.obsDim();
    std::vector<double> obs_sum(obs_dim, 0.0), obs_abs_sum(obs_dim, 0.0);
    std::int64_t obs_samples = 0;
    int s = 0;
    for (; s < steps && (quota == 0 || full < envs); ++s) {
      const StepResult& now = env.state();
      for (int e = 0; obs_from_step >= 0 && e < envs; ++e) {
        if (now.episode_steps[e] < static_cast<std::uint32_t>(obs_from_step)) continue;
        for (int k = 0; k < obs_dim; ++k) {
          const double x = now.observations[static_cast<std::size_t>(e) * obs_dim + k];
          obs_sum[k] += x;
          obs_abs_sum[k] += std::abs(x);
        }
        ++obs_samples;
      }
      policy.act(now.observations, envs, actions);
      std::vector<std::uint32_t> lengths = env.state().episode_steps;
      const StepResult& r = env.step(actions);
      policy.resetMemory(r.reset_env_ids);  // a memory starts over with each episode
      for (float x : r.rewards) reward_sum += x;
      for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
        const std::uint32_t e = r.reset_env_ids[i];
        if (quota == 0 || done[e] >= quota) continue;
        const int rate = outcomeRate(r.outcomes[i]);
        if (rate < 0) continue;  // a round's wait (rounds): no episode
        ++outcome_count[rate];
        if (r.outcomes[i] == static_cast<std::uint8_t>(Outcome::kCollisionMover)) ++mover_hits;
        if (r.outcomes[i] == static_cast<std::uint8_t>(Outcome::kCollisionRobot)) ++robot_hits;
        episode_steps += lengths[e] + 1;
        ++counted;
        if (++done[e] == quota) ++full;
      }
    }
    std::printf("task=%s envs=%d steps=%d\n", env.task().name().c_str(), envs, s);
    std::printf("mean_reward_per_step=%.4f\n", reward_sum / (static_cast<double>(s) * envs));
    if (obs_from_step >= 0) {
      const std::vector<std::string>& names = env.task().observationNames();
      std::printf("obs_samples=%lld\n", static_cast<long long>(obs_samples));
      for (int k = 0; k < obs_dim; ++k) {
        const double n = std::max<std::int64_t>(obs_samples, 1);
        std::printf("obs_mean_%s=%.4f\nobs_mean_abs_%s=%.4f\n", names[k].c_str(), obs_sum[k] / n,
                    names[k].c_str(), obs_abs_sum[k] / n);
      }
    }
    if (quota > 0) {
      const double n = std::max<std::int64_t>(counted, 1);
      std::printf("episodes=%lld%s\n", static_cast<long long>(counted),
                  full < envs ? " (the steps ran out first)" : "");
      std::printf("success_rate=%.4f\ncollision_rate=%.4f\ntimeout_rate=%.4f\n",
                  outcome_count[1] / n, outcome_count[2] / n, outcome_count[0] / n);
      std::printf("mover_collision_rate=%.4f\n", mover_hits / n);  // of collision_rate
      std::printf("robot_collision_rate=%.4f\n", robot_hits / n);  // of collision_rate
      std::printf("mean_episode_steps=%.1f\n", episode_steps / n);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_evaluate: %s\n", e.what());
    return 1;
  }
  return 0;
}
