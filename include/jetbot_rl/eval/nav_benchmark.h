#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/eval/episode_loop.h"
#include "jetbot_rl/eval/navigation_metrics.h"
#include "jetbot_rl/ppo/policy.h"

namespace jetbot_rl {

/// A world of the navigation benchmark: its name and the env it is (the env's own setup with
/// the world's fields set over it).
struct BenchmarkWorld {
  std::string name;
  EnvSetup setup;
};

/// How a policy fared in one world, over the episodes counted.
struct BenchmarkResult {
  int episodes = 0;
  bool steps_ran_out = false;  ///< Not every env finished its quota of episodes.
  double success = 0.0, collision = 0.0, timeout = 0.0;  ///< Shares of the episodes.
  /// Resets whose generated layout could not be made (run in the bare arena instead).
  std::uint64_t layouts_unmade = 0;
  /// Time to goal, path over the shortest, SPL, BARN's score, smoothness (NavigationMetrics).
  NavigationMetricsResult metrics;
};

/// The longest shortest path of the benchmark's worlds, about: a goal 3 m away in the hardest
/// maze, down its corridors [m].
constexpr double kBenchmarkLongestWay = 27.0;
/// The least time an episode of the benchmark has before it is truncated (a time-out) [s].
constexpr double kBenchmarkEpisodeS = 60.0;

/// The time a benchmark episode of a robot of top speed `top_speed` [m/s] has [s]: time to drive
/// kBenchmarkLongestWay at 0.75 of it (the turns), at least kBenchmarkEpisodeS (60 s for the
/// Jetbot's 0.6 m/s; with no top speed known, that).
double benchmarkEpisodeS(double top_speed);

/// The benchmark's worlds over the env `base` (the navigation task set): each generated family
/// at difficulty 0, 0.5 and 1 in a 6 x 6 m arena, goals 1-3 m away; then the map `map` with
/// goals 1-15 m away anywhere the robot can reach (nav/goal_reachable), other rooms included;
/// then, unless `gazebo_world` is empty, that Gazebo world with starts and goals 1-6 m apart
/// anywhere the robot can reach from its spawn, the origin; every episode `episode_s` long [s].
/// The rest of `base` (the robot's control, the scanner, the observation, the other world
/// fields) is kept.
std::vector<BenchmarkWorld> navigationBenchmarkWorlds(const EnvSetup& base, const std::string& map,
                                                      const std::string& gazebo_world,
                                                      double episode_s = kBenchmarkEpisodeS);

/**
 * Plays `policy`'s mean action on `env` (the navigation task, its world) until each env has
 * ended ceil(episodes / envs) episodes or `max_steps` control steps ran (runEpisodes()); counts
 * each episode's outcome and its metrics (NavigationMetrics, the optimal time at `top_speed`
 * [m/s], topSpeed(); 0: none). ConfigError unless the env has the navigation task and a world.
 */
BenchmarkResult runNavigationBenchmark(ppo::Policy& policy, BatchedEnv& env, int episodes,
                                       int max_steps, double top_speed);
/// The same with `actor` acting (DwaActor: the classical baseline).
BenchmarkResult runNavigationBenchmark(EpisodeActor& actor, BatchedEnv& env, int episodes,
                                       int max_steps, double top_speed);

}  // namespace jetbot_rl
