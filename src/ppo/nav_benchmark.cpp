#include "jetbot_rl/ppo/nav_benchmark.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// The shortest path's length from env `e`'s start to its goal [m]; NaN when there is none.
double shortestPath(const BatchedEnv& env, const NavigationTask& task, int e) {
  const EnvLayout& layout = env.view(e).layout();
  const WorldModel& world = *env.world();
  const FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles);
  std::vector<Eigen::Vector2d> path;
  if (!planPath(grid, layout.start, task.goal(e), 0.0, path)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

}  // namespace

double benchmarkEpisodeS(double top_speed) {
  if (!(top_speed > 0.0) || !std::isfinite(top_speed)) return kBenchmarkEpisodeS;
  return std::max(kBenchmarkEpisodeS, kBenchmarkLongestWay / (0.75 * top_speed));
}

std::vector<BenchmarkWorld> navigationBenchmarkWorlds(const std::string& map, double episode_s) {
  // Time for the longest ways: a time-out is a robot that did not get there, not a clock too
  // short for its path (in the hardest mazes a goal 3 m away is up to 27 m down the corridors).
  const std::string episode = "episode_length_s: " + std::to_string(episode_s) + "\n";
  std::vector<BenchmarkWorld> worlds;
  for (const char* family : {"clutter", "rooms", "maze"}) {
    for (const char* difficulty : {"0", "0.5", "1"}) {
      worlds.push_back({std::string(family) + " " + difficulty,
                        episode +
                            "world:\n  map: ''\n  arena_size: [6.0, 6.0]\n  region: []\n"
                            "  num_boxes: 0\n  num_cylinders: 0\n  random_start: true\n"
                            "  start_clearance: 0.3\n  families: [" +
                            std::string(family) + "]\n  family_weights: []\n  difficulty: " +
                            difficulty + "\n  curriculum: false\n"});
    }
  }
  worlds.push_back(
      {"map 1-15 m", episode + "world:\n  map: " + map +
                         "\n  arena_size: []\n  region: []\n  num_boxes: 0\n  num_cylinders: 0\n"
                         "  random_start: true\n  families: []\n  curriculum: false\n"
                         "nav:\n  goal_distance: [1.0, 15.0]\n  goal_reachable: true\n"});
  return worlds;
}

BenchmarkResult runNavigationBenchmark(Policy& policy, BatchedEnv& env, int episodes,
                                       int max_steps) {
  const auto* task = dynamic_cast<const NavigationTask*>(&env.task());
  if (!task || !env.world()) {
    throw ConfigError("the navigation benchmark needs the navigation task in a world (task = " +
                      env.task().name() + ")");
  }
  const int envs = env.numEnvs();
  const int quota = (std::max(episodes, 1) + envs - 1) / envs;
  std::vector<int> done(envs, 0);
  std::vector<double> driven(envs, 0.0), shortest(envs);
  for (int e = 0; e < envs; ++e) shortest[e] = shortestPath(env, *task, e);
  std::vector<Eigen::Vector2d> before(envs), goal(envs);
  const double radius = task->config().goal_radius;
  std::vector<float> actions;
  int full = 0, outcomes[3] = {0, 0, 0}, ratios = 0;
  double time_sum = 0.0, ratio_sum = 0.0;
  policy.resetMemory();
  for (int s = 0; s < max_steps && full < envs; ++s) {
    for (int e = 0; e < envs; ++e) {
      before[e] = env.view(e).rootState().position.head<2>();
      goal[e] = task->goal(e);
    }
    policy.act(env.state().observations, envs, actions);
    const std::vector<std::uint32_t> lengths = env.state().episode_steps;
    const StepResult& r = env.step(actions);
    policy.resetMemory(r.reset_env_ids);
    std::vector<std::uint8_t> reset(envs, 0);
    for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
      const std::uint32_t e = r.reset_env_ids[i];
      reset[e] = 1;
      const int outcome = outcomeRate(r.outcomes[i]);
      if (done[e] < quota && outcome >= 0) {
        ++outcomes[outcome];
        if (outcome == static_cast<int>(Outcome::kSuccess)) {
          time_sum += (lengths[e] + 1) * env.controlDt();
          // The last step (whose end the reset hid) as far as the goal's circle, against the
          // shortest path's length to that circle.
          const double last = std::max(0.0, (goal[e] - before[e]).norm() - radius);
          if (shortest[e] > radius) {
            ratio_sum += (driven[e] + last) / (shortest[e] - radius);
            ++ratios;
          }
        }
        if (++done[e] == quota) ++full;
      }
      driven[e] = 0.0;
      shortest[e] = shortestPath(env, *task, static_cast<int>(e));
    }
    for (int e = 0; e < envs; ++e) {
      if (!reset[e]) driven[e] += (env.view(e).rootState().position.head<2>() - before[e]).norm();
    }
  }
  BenchmarkResult result;
  result.episodes = outcomes[0] + outcomes[1] + outcomes[2];
  result.steps_ran_out = full < envs;
  const double n = std::max(result.episodes, 1);
  result.timeout = outcomes[0] / n;
  result.success = outcomes[1] / n;
  result.collision = outcomes[2] / n;
  result.time_to_goal = outcomes[1] > 0 ? time_sum / outcomes[1] : 0.0;
  result.path_ratio = ratios > 0 ? ratio_sum / ratios : 0.0;
  return result;
}

}  // namespace ppo
}  // namespace jetbot_rl
