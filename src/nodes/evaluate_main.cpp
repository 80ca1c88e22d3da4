// jetbot_rl_evaluate --checkpoint PATH (a file or a run directory: its best.pt) [--task NAME]
// [--config YAML ...] [--num-envs N] [--steps S] [--seed S] [--urdf PATH] [--episodes N]
// [--obs-from-step K]: plays a trained policy's mean action in-process on envs configured by the
// YAML files (EnvSetup: the env node's parameter names: task, reward_variant, randomisation
// ranges, ...), and prints the mean reward per step over every env step; with --obs-from-step the
// mean and mean absolute value of each observation the policy acted on at episode step K or later.
// A navigation policy in a world: the field's metrics too (time to goal, path over the shortest,
// SPL, BARN's score, time over the optimal, smoothness; docs/navigation.md#the-benchmark).
// For evaluating a policy on perturbed physics (docs/sim_to_real.md).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/eval/episode_loop.h"
#include "jetbot_rl/eval/navigation_metrics.h"
#include "jetbot_rl/eval/observation_means.h"
#include "jetbot_rl/planning/speed_limit.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/tasks/road_following_task.h"

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
    if (std::filesystem::is_directory(checkpoint)) checkpoint += "/checkpoints/best.pt";
    ppo::Policy policy(checkpoint);
    EnvSetup setup = env_options.setup();
    if (!task.empty()) fieldsFromYaml("task: " + task, setup);
    setup.env.seed = static_cast<std::uint64_t>(seed);
    const RobotModelConstPtr robot =
        RobotModel::fromUrdfFile(env_options.urdf, EnvProgramOptions::packagePathResolver());
    takeSpeedLimit(policy.meta().spec.observer, *robot, setup.env.speed_limit);  // as trained
    const std::unique_ptr<BatchedEnv> batch = makeEnv(robot, setup);
    BatchedEnv& env = *batch;
    const int envs = env.numEnvs(), steps = env_options.steps;
    for (const std::string& warning : policy.fitTo(env.spec())) {
      std::fprintf(stderr, "warning: %s\n", warning.c_str());
    }
    ObservationMeans means(obs_from_step);
    EpisodeObservers observers;
    observers.add(&means);
    // A navigation policy's episodes in a world: the field's metrics too.
    const auto* navigation = dynamic_cast<const NavigationTask*>(&env.task());
    std::optional<NavigationMetrics> metrics;
    if (navigation && env.world() && episodes > 0) {
      metrics.emplace(env, *navigation, topSpeed(policy.meta().spec));
      observers.add(&*metrics);
    }
    const EpisodeTotals totals = runEpisodes(policy, env, episodes, steps, &observers);
    const int s = totals.steps;
    std::printf("task=%s envs=%d steps=%d\n", env.task().name().c_str(), envs, s);
    std::printf("mean_reward_per_step=%.4f\n", totals.reward_sum / (static_cast<double>(s) * envs));
    if (obs_from_step >= 0) means.print(env.task().observationNames());
    if (episodes > 0) {
      const double n = std::max<std::int64_t>(totals.episodes, 1);
      std::printf("episodes=%lld%s\n", static_cast<long long>(totals.episodes),
                  totals.steps_ran_out ? " (the steps ran out first)" : "");
      std::printf("success_rate=%.4f\ncollision_rate=%.4f\ntimeout_rate=%.4f\n",
                  totals.outcomes[1] / n, totals.outcomes[2] / n, totals.outcomes[0] / n);
      std::printf("mover_collision_rate=%.4f\n", totals.mover_collisions / n);  // of collisions
      std::printf("robot_collision_rate=%.4f\n", totals.robot_collisions / n);  // of collisions
      if (dynamic_cast<const RoadFollowingTask*>(&env.task())) {
        std::printf("off_track_rate=%.4f\n", totals.off_track / n);  // the collision rate's
      }
      std::printf("mean_episode_steps=%.1f\n", totals.episode_steps / n);
      if (metrics) {
        const NavigationMetricsResult m = metrics->result();
        std::printf("time_to_goal=%.2f\npath_over_shortest=%.3f\nspl=%.4f\n", m.time_to_goal,
                    m.path_ratio, m.spl);
        std::printf("barn_score=%.4f\ntime_over_optimal=%.3f\n", m.barn_score, m.time_ratio);
        std::printf("yaw_acceleration=%.3f\nforward_acceleration=%.3f\n", m.angular_smoothness,
                    m.linear_smoothness);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_evaluate: %s\n", e.what());
    return 1;
  }
  return 0;
}
