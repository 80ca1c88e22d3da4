// jetbot_rl_nav_benchmark --checkpoint PATH (a file, or a run directory: its latest.pt, else its
// best.pt) [--episodes N] [--seed S] [--map YAML] [--gazebo-world WORLD] [--planners policy,dwa]
// [--worlds NAME,...] [--config YAML
// ...] [--num-envs N] [--steps S] [--threads T] [--urdf PATH]: the navigation benchmark
// (config/navigation_env.yaml, then the --config files: those the policy was trained with)
// (docs/navigation.md#the-benchmark): a navigation policy in each generated family at three
// difficulties, in a map and in a Gazebo world (default worlds/furnished_room.world, "" for none)
// with goals anywhere reachable, on a seed not used in training; one
// row per world: success, collision and time-out rates, time to goal, path over the shortest,
// SPL, BARN's score, time over the optimal time and the yaw rate's mean change [rad/s^2].
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/config/yaml_flatten.h"
#include "jetbot_rl/eval/dwa_actor.h"
#include "jetbot_rl/eval/nav_benchmark.h"
#include "jetbot_rl/planning/speed_limit.h"
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
  bool policy_rows = true, dwa_rows = true;
  std::set<std::string> only;  // --worlds: these rows only
  const auto take = [&](const std::string& option, const std::string& value, std::string& why) {
    if (option == "--map") {
      map = value;
    } else if (option == "--gazebo-world") {
      gazebo_world = value;
    } else if (option == "--worlds") {
      only.clear();
      std::stringstream names(value);
      for (std::string name; std::getline(names, name, ',');) only.insert(name);
    } else if (option == "--planners") {
      policy_rows = value == "policy" || value == "policy,dwa" || value == "dwa,policy";
      dwa_rows = value == "dwa" || value == "policy,dwa" || value == "dwa,policy";
      if (!policy_rows && !dwa_rows) {
        why = "invalid --planners = " + value + " (policy, dwa or policy,dwa)";
      }
    } else {
      return false;
    }
    return true;
  };
  if (!options.parse(
          argc, argv, "jetbot_rl_nav_benchmark",
          "[--map YAML] [--gazebo-world WORLD] [--planners policy,dwa] [--worlds NAME,...]",
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
    // The robot's top speed sets the episodes' time (a slow robot needs longer) and the optimal
    // time of BARN's score.
    const double top_speed = topSpeed(policy.meta().spec);
    const double episode_s = benchmarkEpisodeS(top_speed);
    std::printf("# %s: %d episodes per world of %.0f s, seed %lld, %s\n", checkpoint.c_str(),
                episodes, episode_s, seed, path ? "with its global path" : "without a path");
    std::printf("%-14s %-7s %8s %8s %9s %8s %12s %13s %6s %6s %8s %12s\n", "world", "planner",
                "episodes", "success", "collision", "timeout", "time_to_goal", "path/shortest",
                "spl", "barn", "time/opt", "yaw_acc");
    const auto row = [](const std::string& world, const char* planner, const BenchmarkResult& r) {
      const NavigationMetricsResult& m = r.metrics;
      std::printf("%-14s %-7s %8d %8.3f %9.3f %8.3f %11.1fs %13.2f %6.3f %6.3f %8.2f %12.2f%s\n",
                  world.c_str(), planner, r.episodes, r.success, r.collision, r.timeout,
                  m.time_to_goal, m.path_ratio, m.spl, m.barn_score, m.time_ratio,
                  m.angular_smoothness, r.steps_ran_out ? "  (the steps ran out first)" : "");
      // An easier row than its name says: never silently.
      if (r.layouts_unmade > 0) {
        std::printf(
            "#   %s: %llu generated layouts could not be made (in the bare arena instead)\n",
            world.c_str(), static_cast<unsigned long long>(r.layouts_unmade));
      }
      std::fflush(stdout);
    };
    // The classical baseline at the robot's top speed, its dwa/... parameters from the --config
    // files over DwaConfig's defaults.
    DwaConfig dwa;
    if (top_speed > 0.0) dwa.max_vel_x = top_speed;
    for (const std::string& file : env_options.configs) {
      std::ifstream in(file);
      std::ostringstream text;
      text << in.rdbuf();
      try {
        fieldsFromYaml(flattenYaml(text.str()), dwa);
      } catch (const ConfigError& e) {
        throw ConfigError(file + ": " + e.what());
      }
    }
    validateConfig(dwa);
    EnvSetup base = env_options.setup();
    takeObservationContract(contract, base.task.navigation);
    base.env.seed = static_cast<std::uint64_t>(seed);
    const RobotModelConstPtr robot =
        RobotModel::fromUrdfFile(env_options.urdf, EnvProgramOptions::packagePathResolver());
    takeSpeedLimit(contract, *robot, base.env.speed_limit);  // the policy drives as it was trained
    for (const BenchmarkWorld& world :
         navigationBenchmarkWorlds(base, map, gazebo_world, episode_s)) {
      if (!only.empty() && !only.count(world.name)) continue;
      if (policy_rows) {
        const std::unique_ptr<BatchedEnv> env = makeEnv(robot, world.setup);
        for (const std::string& warning : policy.fitTo(env->spec())) {
          // The benchmark's own episode length (kBenchmarkEpisodeS) is no surprise to warn of.
          if (warning.rfind("the env's max_episode_length", 0) == 0) continue;
          std::fprintf(stderr, "warning: %s\n", warning.c_str());
        }
        row(world.name, "policy",
            runNavigationBenchmark(policy, *env, episodes, env_options.steps, top_speed));
      }
      if (dwa_rows) {
        // The same worlds, seeds and global path (planned whether the policy observes one).
        EnvSetup setup = world.setup;
        setup.task.navigation.path = true;
        setup.env.speed_limit.enabled = false;  // move_base's planner as it is, no monitor
        const std::unique_ptr<BatchedEnv> env = makeEnv(robot, setup);
        DwaActor actor(*env, dwa);
        row(world.name, "dwa",
            runNavigationBenchmark(actor, *env, episodes, env_options.steps, top_speed));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_nav_benchmark: %s\n", e.what());
    return 1;
  }
  return 0;
}
