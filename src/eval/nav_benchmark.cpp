#include "jetbot_rl/eval/nav_benchmark.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/eval/episode_loop.h"
#include "jetbot_rl/eval/navigation_metrics.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {

double benchmarkEpisodeS(double top_speed) {
  if (!(top_speed > 0.0) || !std::isfinite(top_speed)) return kBenchmarkEpisodeS;
  return std::max(kBenchmarkEpisodeS, kBenchmarkLongestWay / (0.75 * top_speed));
}

std::vector<BenchmarkWorld> navigationBenchmarkWorlds(const EnvSetup& base, const std::string& map,
                                                      const std::string& gazebo_world,
                                                      double episode_s) {
  EnvSetup common = base;
  common.task.task = TaskKind::kNavigation;
  // Time for the longest ways: a time-out is a robot that did not get there, not a clock too
  // short for its path (in the hardest mazes a goal 3 m away is up to 27 m down the corridors).
  common.env.episode_length_s = episode_s;
  WorldConfig& world = common.env.world;
  world.map.clear();
  world.region.clear();
  world.num_boxes = 0;
  world.num_cylinders = 0;
  world.random_start = true;
  world.curriculum = false;
  std::vector<BenchmarkWorld> worlds;
  // A generated family's layouts in a 6 x 6 m arena, at one difficulty.
  const auto generated = [&](const std::string& name, const std::string& family,
                             double difficulty) -> WorldConfig& {
    worlds.push_back(BenchmarkWorld{name, common});
    WorldConfig& w = worlds.back().setup.env.world;
    w.arena_size = {6.0, 6.0};
    w.start_clearance = 0.3;
    w.families = {family};
    w.family_weights.clear();
    w.difficulty = difficulty;
    return w;
  };
  for (const char* family : {"clutter", "rooms", "maze", "barn"}) {
    for (const char* difficulty : {"0", "0.5", "1"}) {
      WorldConfig& w =
          generated(std::string(family) + " " + difficulty, family, std::stod(difficulty));
      // A BARN field of 6 x 6 m holds about 1,200 posts at 1: none left out.
      if (w.families[0] == "barn") {
        w.max_generated_obstacles = std::max(w.max_generated_obstacles, 4000);
      }
    }
  }
  // Tight passages: the densest clutter and rooms with their narrowest gaps and doors 1.3 and
  // 1.05 robot widths (the BARN benchmark's narrowest for a Jackal), where a family's hardest
  // keeps 1.5.
  for (const char* family : {"clutter", "rooms"}) {
    for (const char* widths : {"1.3", "1.05"}) {
      generated(std::string(family) + " " + widths + "w", family, 1.0).passage_widths =
          std::vector<double>(2, std::stod(widths));
    }
  }
  BenchmarkWorld office{"map 1-15 m", common};
  office.setup.env.world.map = map;
  office.setup.env.world.arena_size.clear();
  office.setup.env.world.families.clear();
  office.setup.task.navigation.goal_distance = {1.0, 15.0};
  office.setup.task.navigation.goal_reachable = true;
  worlds.push_back(std::move(office));
  if (gazebo_world.empty()) return worlds;
  // A world no one trained in, as published Gazebo worlds are: starts and goals where the robot
  // can drive from the spawn (WorldModel::spawnReach()), not outside it or inside furniture.
  BenchmarkWorld gazebo{"gazebo 1-6 m", common};
  WorldConfig& room = gazebo.setup.env.world;
  room.gazebo_world = gazebo_world;
  room.arena_size.clear();
  room.families.clear();
  room.spawn = {0.0, 0.0};
  gazebo.setup.task.navigation.goal_distance = {1.0, 6.0};
  gazebo.setup.task.navigation.goal_reachable = true;
  worlds.push_back(std::move(gazebo));
  return worlds;
}

BenchmarkResult runNavigationBenchmark(ppo::Policy& policy, BatchedEnv& env, int episodes,
                                       int max_steps, double top_speed) {
  policy.resetMemory();
  PolicyActor actor(policy);
  return runNavigationBenchmark(actor, env, episodes, max_steps, top_speed);
}

BenchmarkResult runNavigationBenchmark(EpisodeActor& actor, BatchedEnv& env, int episodes,
                                       int max_steps, double top_speed) {
  const auto* task = dynamic_cast<const NavigationTask*>(&env.task());
  if (!task || !env.world()) {
    throw ConfigError("the navigation benchmark needs the navigation task in a world (task = " +
                      env.task().name() + ")");
  }
  NavigationMetrics metrics(env, *task, top_speed);
  const std::uint64_t unmade_before = env.layoutsUnmade();
  const EpisodeTotals totals = runEpisodes(actor, env, std::max(episodes, 1), max_steps, &metrics);
  BenchmarkResult result;
  result.episodes = static_cast<int>(totals.episodes);
  result.steps_ran_out = totals.steps_ran_out;
  const double n = std::max(result.episodes, 1);
  result.timeout = totals.outcomes[0] / n;
  result.success = totals.outcomes[1] / n;
  result.collision = totals.outcomes[2] / n;
  result.metrics = metrics.result();
  result.layouts_unmade = env.layoutsUnmade() - unmade_before;
  return result;
}

}  // namespace jetbot_rl
