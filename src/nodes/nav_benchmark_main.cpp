// jetbot_rl_nav_benchmark --checkpoint PATH (a file, or a run directory: its latest.pt, else its
// best.pt) [--episodes N] [--seed S] [--map YAML] [--gazebo-world WORLD] [--config YAML
// ...] [--num-envs N] [--steps S] [--threads T] [--urdf PATH]: the navigation benchmark
// (config/navigation_env.yaml, then the --config files: those the policy was trained with)
// (docs/navigation.md#the-benchmark): a navigation policy in each generated family at three
// difficulties, in a map and in a Gazebo world (default worlds/furnished_room.world, "" for none)
// with goals anywhere reachable, on a seed not used in training; one
// row per world: success, collision and time-out rates, time to goal, path over the shortest.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/eval/nav_benchmark.h"
#include "jetbot_rl/tasks/navigation_task.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  PolicyProgramOptions options;
  EnvProgramOptions& env_options = options.env;
  env_options.num_envs = 50;
  env_options.steps = 20000;
  env_options.threads = 2;
  env_options.urdf = JETBOT_RL_DEFAULT_LIDAR_URDF;
  options.episodes = 200;
  std::string map = JETBOT_RL_DEFAULT_MAP;
  std::string gazebo_world = JETBOT_RL_DEFAULT_GAZEBO_WORLD;
  const auto take = [&](const std::string& option, const std::string& value, std::string&) {
    if (option == "--map") {
      map = value;
    } else if (option == "--gazebo-world") {
      gazebo_world = value;
    } else {
      return false;
    }
    return true;
  };
  if (!options.parse(argc, argv, "jetbot_rl_nav_benchmark", "[--map YAML] [--gazebo-world WORLD]",
                     take)) {
    return 2;
  }
  std::string checkpoint = options.checkpoint;
  const long long seed = options.seed;
  const int episodes = std::max(options.episodes, 1);
  env_options.configs.insert(env_options.configs.begin(), JETBOT_RL_NAVIGATION_ENV);
  try {
    if (std::filesystem::is_directory(checkpoint)) {
      // A run's newest state; a shipped policy (policies/) keeps only its best.pt.
      const std::string latest = checkpoint + "/checkpoints/latest.pt";
      checkpoint = std::filesystem::exists(latest) ? latest : checkpoint + "/checkpoints/best.pt";
    }
    ppo::Policy policy(checkpoint);
    ppo::requireObservationContract(policy.meta(), checkpoint);
    const ObserverSpec& contract = policy.meta().spec.observer;
    const bool path = contract.path_lookahead > 0.0;
    // A twist policy's top speed sets the episodes' time (a slow robot needs longer).
    const BatchSpec& trained = policy.meta().spec;
    const double episode_s = benchmarkEpisodeS(
        actsByTwist(trained) && !trained.action_high.empty() ? trained.action_high[0] : 0.0);
    std::printf("# %s: %d episodes per world of %.0f s, seed %lld, %s\n", checkpoint.c_str(),
                episodes, episode_s, seed, path ? "with its global path" : "without a path");
    std::printf("%-14s %8s %8s %9s %8s %12s %13s\n", "world", "episodes", "success", "collision",
                "timeout", "time_to_goal", "path/shortest");
    EnvSetup base = env_options.setup();
    takeObservationContract(contract, base.task.navigation);
    base.env.seed = static_cast<std::uint64_t>(seed);
    const RobotModelConstPtr robot =
        RobotModel::fromUrdfFile(env_options.urdf, EnvProgramOptions::packagePathResolver());
    for (const BenchmarkWorld& world :
         navigationBenchmarkWorlds(base, map, gazebo_world, episode_s)) {
      const std::unique_ptr<BatchedEnv> env = makeEnv(robot, world.setup);
      for (const std::string& warning : policy.fitTo(env->spec())) {
        // The benchmark's own episode length (kBenchmarkEpisodeS) is no surprise to warn of.
        if (warning.rfind("the env's max_episode_length", 0) == 0) continue;
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
      }
      const BenchmarkResult r = runNavigationBenchmark(policy, *env, episodes, env_options.steps);
      std::printf("%-14s %8d %8.3f %9.3f %8.3f %11.1fs %13.2f%s\n", world.name.c_str(), r.episodes,
                  r.success, r.collision, r.timeout, r.time_to_goal, r.path_ratio,
                  r.steps_ran_out ? "  (the steps ran out first)" : "");
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_nav_benchmark: %s\n", e.what());
    return 1;
  }
  return 0;
}
