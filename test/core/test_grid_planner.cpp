// The global path (issue 30, part 4): the planner's shortest paths on hand-made layouts, no path
// where walls or the footprint close the way, paths keeping off walls where there is room, the
// path tracker, and the navigation task observing and following a planned path.
#include <gtest/gtest.h>

#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"
#include "jetbot_rl/planning/path_tracker.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

constexpr double kRadius = 0.1;

WorldModel arena(double x, double y) {
  WorldConfig c;
  c.arena_size = {x, y};
  return WorldModel(c, kRadius);
}

Obstacle wallBox(double cx, double cy, double hx, double hy) {
  Obstacle o;
  o.center = {cx, cy};
  o.half_extents = {hx, hy};
  o.height = 0.5;
  return o;
}

/// A wall across a 4 x 4 m arena at x = 0 with a door of `door` [m] at y in [1 - door, 1].
std::vector<Obstacle> wallWithDoor(double door) {
  const double top = 1.0, bottom = 1.0 - door;
  return {wallBox(0.0, 0.5 * (top + 2.0), 0.05, 0.5 * (2.0 - top)),
          wallBox(0.0, 0.5 * (bottom - 2.0), 0.05, 0.5 * (bottom + 2.0))};
}

/// Every point of the path, each 1 cm, keeps the footprint from the world and the obstacles.
void expectClear(const WorldModel& world, const std::vector<Obstacle>& obstacles,
                 const std::vector<Eigen::Vector2d>& path, double radius) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double l = (path[i] - path[i - 1]).norm();
    for (double s = 0.0; s <= l; s += 0.01) {
      const Eigen::Vector2d p = path[i - 1] + (l > 0 ? s / l : 0.0) * (path[i] - path[i - 1]);
      ASSERT_GT(world.clearance(p, &obstacles), radius - 0.036)  // a cell's half diagonal
          << "at " << p.transpose();
    }
  }
}

TEST(GridPlanner, TheShortestWayGoesThroughTheDoor) {
  const WorldModel world = arena(4.0, 4.0);
  const auto walls = wallWithDoor(0.6);
  const FootprintGrid grid(world, 0.05, kRadius, walls);
  std::vector<Eigen::Vector2d> path;
  const Eigen::Vector2d start(-1.5, -1.5), goal(1.5, -1.5);
  ASSERT_TRUE(planPath(grid, start, goal, 0.0, path));
  EXPECT_EQ(path.front(), start);
  EXPECT_EQ(path.back(), goal);
  // Through the door's lower corner, inflated by the footprint: about start -> (0, 0.3) -> goal.
  const Eigen::Vector2d corner(0.0, 0.4 + kRadius);
  const double shortest = (corner - start).norm() + (goal - corner).norm();
  EXPECT_GT(test::pathLength(path), shortest - 0.15);
  EXPECT_LT(test::pathLength(path), shortest * 1.08 + 0.1);
  bool through_door = false;
  for (const auto& p : path) through_door |= std::abs(p.x()) < 0.2 && p.y() > 0.35 && p.y() < 1.0;
  EXPECT_TRUE(through_door);
  expectClear(world, walls, path, kRadius);
}

TEST(GridPlanner, NoPathWhereAWallOrTheFootprintClosesTheWay) {
  const WorldModel world = arena(4.0, 4.0);
  std::vector<Eigen::Vector2d> path{{9, 9}};
  const Eigen::Vector2d start(-1.5, 0.5), goal(1.5, 0.5);
  // No door: no path.
  const std::vector<Obstacle> closed{wallBox(0.0, 0.0, 0.05, 2.0)};
  EXPECT_FALSE(planPath(FootprintGrid(world, 0.05, kRadius, closed), start, goal, 0.0, path));
  EXPECT_TRUE(path.empty());
  // A door narrower than the robot (0.15 m < 0.2 m): none; a little wider than it: one.
  EXPECT_FALSE(
      planPath(FootprintGrid(world, 0.05, kRadius, wallWithDoor(0.15)), start, goal, 0.0, path));
  EXPECT_TRUE(
      planPath(FootprintGrid(world, 0.05, kRadius, wallWithDoor(0.35)), start, goal, 0.0, path));
  // A start or a goal inside an obstacle or outside the world: none.
  const auto walls = wallWithDoor(0.6);
  const FootprintGrid grid(world, 0.05, kRadius, walls);
  EXPECT_FALSE(planPath(grid, Eigen::Vector2d(0.0, -1.0), goal, 0.0, path));
  EXPECT_FALSE(planPath(grid, start, Eigen::Vector2d(2.5, 0.0), 0.0, path));
  EXPECT_FALSE(planPath(grid, start, Eigen::Vector2d(NAN, 0.0), 0.0, path));
}

TEST(GridPlanner, PathsKeepOffWallsWhereThereIsRoom) {
  // Along a wall: without the clearance cost the path hugs the inflated wall; with it, the path
  // keeps its clearance where the room allows.
  const WorldModel world = arena(4.0, 4.0);
  const std::vector<Obstacle> wall{wallBox(0.0, -0.5, 1.0, 0.05)};
  const Eigen::Vector2d start(-1.5, -0.2), goal(1.5, -0.2);
  const FootprintGrid grid(world, 0.05, kRadius, wall, 0.3);
  std::vector<Eigen::Vector2d> tight, roomy;
  ASSERT_TRUE(planPath(grid, start, goal, 0.0, tight));
  ASSERT_TRUE(planPath(grid, start, goal, 2.0, roomy));
  const auto midClearance = [&](const std::vector<Eigen::Vector2d>& path) {
    double worst = 1e9;
    for (const auto& p : path) {
      if (std::abs(p.x()) < 0.8) worst = std::min(worst, world.clearance(p, &wall));
    }
    for (std::size_t i = 1; i < path.size(); ++i) {  // segments crossing x = 0
      if ((path[i - 1].x() < 0) != (path[i].x() < 0)) {
        const double t = -path[i - 1].x() / (path[i].x() - path[i - 1].x());
        const Eigen::Vector2d p = path[i - 1] + t * (path[i] - path[i - 1]);
        worst = std::min(worst, world.clearance(p, &wall));
      }
    }
    return worst;
  };
  EXPECT_LT(midClearance(tight), 0.3);
  EXPECT_GT(midClearance(roomy), kRadius + 0.25);
  EXPECT_LT(test::pathLength(roomy), test::pathLength(tight) + 0.5);
}

TEST(PathTracker, FollowsAnLPathAndLooksAhead) {
  PathTracker t;
  t.reset({{0, 0}, {2, 0}, {2, 2}});
  EXPECT_DOUBLE_EQ(t.length(), 4.0);
  t.track({1.0, 0.1});
  EXPECT_NEAR(t.remaining({1.0, 0.1}), 3.0 + 0.1, 1e-12);
  EXPECT_TRUE(t.lookahead(0.5).isApprox(Eigen::Vector2d(1.5, 0.0)));
  t.track({1.9, 0.2});  // nearer the second leg (0.1 m) than the first (0.2 m)
  EXPECT_TRUE(t.lookahead(0.5).isApprox(Eigen::Vector2d(2.0, 0.7)));
  t.track({2.1, 1.8});
  EXPECT_NEAR(t.remaining({2.1, 1.8}), 0.2 + 0.1, 1e-12);
  EXPECT_TRUE(t.lookahead(0.5).isApprox(Eigen::Vector2d(2.0, 2.0)));  // the goal at the end
  t.track({2.0, 2.0});
  EXPECT_NEAR(t.remaining({2.0, 2.0}), 0.0, 1e-12);
}

TEST(PathTracker, APathFoldingBackIsNotJumpedAcross) {
  // A U: out along y = 0, back along y = 0.4 (a wall between them). A robot at the start of the
  // first leg, nearer the second leg's end than to nothing, stays on its own leg.
  PathTracker t;
  t.reset({{0, 0}, {3, 0}, {3, 0.4}, {0, 0.4}});
  t.track({0.5, 0.15});
  EXPECT_NEAR(t.remaining({0.5, 0.15}), 6.4 - 0.5 + 0.15, 1e-12);
  EXPECT_GT(t.lookahead(0.6).x(), 1.0);  // ahead on the first leg, not on the way back
}

EnvConfig pathConfig(int envs, int threads) {
  EnvConfig c = test::scanningArenaConfig(envs, threads);
  c.episode_length_s = 0.1;  // a new layout every few steps
  c.world.start_clearance = 0.3;
  c.world.families = {"rooms", "maze"};
  c.world.difficulty = 0.5;
  return c;
}

std::unique_ptr<Task> pathTask() { return test::navigationTask(true); }

TEST(NavigationPath, TheTaskPlansAPathOnEachLayoutAndObservesIt) {
  BatchedEnv env(test::jetbot(), pathConfig(6, 2), pathTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  const std::vector<std::string>& names = env.spec().observation_names;
  ASSERT_EQ(names[27], "path_remaining");
  ASSERT_EQ(names[28], "path_cos");
  ASSERT_EQ(names[29], "path_sin");
  EXPECT_EQ(names[30], "lin_vel_b_x");
  int planned = 0, longer = 0;
  for (int s = 0; s < 40; ++s) {
    Rng rng(s);
    std::vector<float> a(12);
    for (float& x : a) x = static_cast<float>(20.0 * rng.uniform() - 5.0);
    const StepResult& r = env.step(a);
    for (int e : r.reset_env_ids) {
      const EnvLayout& l = env.view(e).layout();
      const auto& path = task.path(e);
      ASSERT_GE(path.size(), 2u);
      EXPECT_EQ(path.front(), l.start);
      EXPECT_EQ(path.back(), task.goal(e));
      expectClear(*env.world(), l.obstacles, path, env.world()->robotRadius());
      ++planned;
      longer += test::pathLength(path) > (task.goal(e) - l.start).norm() + 0.3;  // round walls
      // What is observed: the path left, and the direction of a point 0.6 m along it.
      const float* obs = &r.observations[static_cast<std::size_t>(e) * names.size()];
      EXPECT_NEAR(obs[27], test::pathLength(path), 1e-4);
      const RootState root = env.view(e).rootState();
      PathTracker t;
      t.reset(path);
      const Eigen::Vector2d ahead = t.lookahead(0.6) - root.position.head<2>();
      const Eigen::Vector3d forward = root.orientation * Eigen::Vector3d::UnitX();
      const double yaw = std::atan2(forward.y(), forward.x());
      const Eigen::Vector2d in_robot = Eigen::Rotation2Dd(-yaw) * ahead.normalized();
      EXPECT_NEAR(obs[28], in_robot.x(), 1e-5);
      EXPECT_NEAR(obs[29], in_robot.y(), 1e-5);
    }
  }
  EXPECT_GT(planned, 20);
  EXPECT_GT(longer, 3);  // rooms and mazes: paths round their walls
  EXPECT_EQ(task.pathsUnplanned(), 0u);
}

TEST(NavigationPath, ProgressIsRewardedAlongThePathNotStraightAtTheGoal) {
  // A goal behind a wall with a way round its top end: half a metre along the path earns the
  // progress reward for half a metre; half a metre straight at the goal (into the wall) less.
  const WorldModel world = arena(4.0, 4.0);
  ScannerSpec scanner;
  scanner.samples = 8;
  scanner.range_max = 4.0;
  NavigationConfig config;
  config.beams = 8;
  config.path = true;
  config.step_cost = 0.0;
  NavigationTask task(config);
  TaskContext context;
  context.scanner = &scanner;
  context.world = &world;
  context.action_dim = 2;
  task.attach(context);
  task.resize(1);
  Rng rng(1);
  task.resetEnv(0, rng);
  task.setGoal(0, {1.5, -1.0});
  EnvLayout layout;
  layout.start = {-1.5, -1.0};
  layout.obstacles = {wallBox(0.0, -0.5, 0.05, 1.5)};  // y in [-2, 1]: the way is round y = 1
  const auto rewardAt = [&](const Eigen::Vector2d& p) {
    task.layoutDrawn(0, world, layout);
    task.sense(0, {nullptr, false, nullptr});
    RootState s;
    s.position = Eigen::Vector3d(p.x(), p.y(), 0.03);
    return task.reward(0, s);
  };
  task.layoutDrawn(0, world, layout);
  ASSERT_GT(test::pathLength(task.path(0)), 3.0 + 2.0 * (1.0 + kRadius) - 0.5);
  const std::vector<Eigen::Vector2d> path = task.path(0);
  const Eigen::Vector2d along = path[0] + 0.5 * (path[1] - path[0]).normalized();
  EXPECT_NEAR(rewardAt(along), config.progress_reward * 0.5, 1e-6);
  EXPECT_LT(rewardAt({-1.0, -1.0}), config.progress_reward * 0.5 - 2.0);
  EXPECT_EQ(task.pathsUnplanned(), 0u);
  // A goal the robot cannot reach (inside the wall): the straight line stands in, counted.
  task.setGoal(0, {0.0, -1.0});
  task.layoutDrawn(0, world, layout);
  EXPECT_EQ(task.pathsUnplanned(), 1u);
  EXPECT_EQ(task.path(0).size(), 2u);
}

TEST(NavigationPath, APathNeedsAWorldAndTheSameSeedPlansTheSameOnAnyThreadCount) {
  EnvConfig bare = test::smallConfig(1, 1);
  bare.scan.link = "base_link";
  bare.scan.samples = 24;
  try {
    BatchedEnv env(test::jetbot(), bare, pathTask());
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("nav/path = true"), std::string::npos) << e.what();
  }
  BatchedEnv one(test::jetbot(), pathConfig(6, 1), pathTask());
  BatchedEnv three(test::jetbot(), pathConfig(6, 3), pathTask());
  for (int s = 0; s < 60; ++s) {
    std::vector<float> a(12, static_cast<float>(s % 7));
    ASSERT_EQ(one.step(a).observations, three.step(a).observations) << "step " << s;
    ASSERT_EQ(one.step(a).rewards, three.step(a).rewards) << "step " << s;
  }
}

TEST(NavigationPath, GoalReachableDrawsGoalsOnlyWhereTheRobotCanDrive) {
  // A 4 x 2 m map cut in two by a wall at x = 2 m, starts drawn over both halves (the map as
  // world/region): with nav/goal_reachable every goal is on its start's side; without, some are
  // behind the wall.
  std::vector<std::string> rows(20, std::string(40, '.'));
  for (std::string& row : rows) row[20] = '#';
  const std::string yaml = test::writeMapYaml("halves.yaml", test::writePgm("halves.pgm", rows));
  EnvConfig c = test::smallConfig(8, 2);
  c.episode_length_s = 0.05;
  c.world.map = yaml;
  c.world.random_start = true;
  c.world.region = {0.0, 0.0, 4.0, 2.0};
  c.world.start_clearance = 0.2;
  c.scan.link = "base_link";
  c.scan.samples = 24;
  const auto crossings = [&](bool reachable) {
    TaskConfig t;
    t.task = TaskKind::kNavigation;
    t.navigation.goal_distance = {1.0, 3.0};
    t.navigation.goal_clearance = 0.2;
    t.navigation.goal_reachable = reachable;
    BatchedEnv env(test::jetbot(), c, makeTask(t));
    const auto& task = dynamic_cast<const NavigationTask&>(env.task());
    int crossed = 0, goals = 0;
    for (int s = 0; s < 60; ++s) {
      for (int e : env.step(std::vector<float>(16, 0.0f)).reset_env_ids) {
        crossed += (env.view(e).layout().start.x() < 2.0) != (task.goal(e).x() < 2.0);
        ++goals;
      }
    }
    EXPECT_GT(goals, 100);
    return crossed;
  };
  EXPECT_EQ(crossings(true), 0);
  EXPECT_GT(crossings(false), 10);
}

}  // namespace
}  // namespace jetbot_rl
