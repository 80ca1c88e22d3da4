#include "jetbot_rl/eval/nav_benchmark.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/eval/episode_loop.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
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

/// The benchmark's bookkeeping of each success's time and path.
class PathWatch : public EpisodeObserver {
 public:
  PathWatch(const BatchedEnv& env, const NavigationTask& task)
      : task_(task),
        radius_(task.config().goal_radius),
        control_dt_(env.controlDt()),
        driven_(env.numEnvs(), 0.0),
        shortest_(env.numEnvs()),
        before_(env.numEnvs()),
        goal_(env.numEnvs()) {
    for (int e = 0; e < env.numEnvs(); ++e) shortest_[e] = shortestPath(env, task_, e);
  }

  void beforeStep(const BatchedEnv& env) override {
    for (int e = 0; e < env.numEnvs(); ++e) {
      before_[e] = env.view(e).rootState().position.head<2>();
      goal_[e] = task_.goal(e);
    }
  }

  void episodeEnded(int e, std::uint8_t outcome, std::uint32_t steps) override {
    if (outcome != static_cast<std::uint8_t>(Outcome::kSuccess)) return;
    ++successes_;
    time_sum_ += steps * control_dt_;
    // The last step (whose end the reset hid) as far as the goal's circle, against the shortest
    // path's length to that circle.
    const double last = std::max(0.0, (goal_[e] - before_[e]).norm() - radius_);
    if (shortest_[e] > radius_) {
      ratio_sum_ += (driven_[e] + last) / (shortest_[e] - radius_);
      ++ratios_;
    }
  }

  void afterStep(const BatchedEnv& env, const StepResult& r) override {
    std::vector<std::uint8_t> reset(env.numEnvs(), 0);
    for (std::uint32_t e : r.reset_env_ids) {
      reset[e] = 1;
      driven_[e] = 0.0;
      shortest_[e] = shortestPath(env, task_, static_cast<int>(e));
    }
    for (int e = 0; e < env.numEnvs(); ++e) {
      if (!reset[e]) driven_[e] += (env.view(e).rootState().position.head<2>() - before_[e]).norm();
    }
  }

  double meanTime() const { return successes_ > 0 ? time_sum_ / successes_ : 0.0; }
  double meanRatio() const { return ratios_ > 0 ? ratio_sum_ / ratios_ : 0.0; }

 private:
  const NavigationTask& task_;
  const double radius_, control_dt_;
  std::vector<double> driven_, shortest_;
  std::vector<Eigen::Vector2d> before_, goal_;
  int successes_ = 0, ratios_ = 0;
  double time_sum_ = 0.0, ratio_sum_ = 0.0;
};

}  // namespace

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
  for (const char* family : {"clutter", "rooms", "maze"}) {
    for (const double difficulty : {0.0, 0.5, 1.0}) {
      BenchmarkWorld w{std::string(family) + " " +
                           (difficulty == 0.0   ? "0"
                            : difficulty == 0.5 ? "0.5"
                                                : "1"),
                       common};
      WorldConfig& generated = w.setup.env.world;
      generated.arena_size = {6.0, 6.0};
      generated.start_clearance = 0.3;
      generated.families = {family};
      generated.family_weights.clear();
      generated.difficulty = difficulty;
      worlds.push_back(std::move(w));
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
                                       int max_steps) {
  const auto* task = dynamic_cast<const NavigationTask*>(&env.task());
  if (!task || !env.world()) {
    throw ConfigError("the navigation benchmark needs the navigation task in a world (task = " +
                      env.task().name() + ")");
  }
  PathWatch paths(env, *task);
  policy.resetMemory();
  const EpisodeTotals totals = runEpisodes(policy, env, std::max(episodes, 1), max_steps, &paths);
  BenchmarkResult result;
  result.episodes = static_cast<int>(totals.episodes);
  result.steps_ran_out = totals.steps_ran_out;
  const double n = std::max(result.episodes, 1);
  result.timeout = totals.outcomes[0] / n;
  result.success = totals.outcomes[1] / n;
  result.collision = totals.outcomes[2] / n;
  result.time_to_goal = paths.meanTime();
  result.path_ratio = paths.meanRatio();
  return result;
}

}  // namespace jetbot_rl
