// Several robots among random obstacles (robots_per_env with world/num_boxes, num_cylinders)
// and in generated layouts (world/families): the robots of a world share its obstacles, start
// and aim clear of them (in a layout: on its free floor, with a path to their goals) and collide
// with them; one robot starts anew among the old obstacles, all of them among new ones; the same
// on any thread count, with rounds and with people.
#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/world/world_generation.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

constexpr int kMates = 3;

/// `num_envs` 4 x 4 m arenas of 3 boxes and 2 cylinders, `kMates` scanning robots each.
EnvConfig clutteredTeam(int num_envs, int threads = 1) {
  EnvConfig c = test::scanningArenaConfig(num_envs, threads);
  c.team.robots_per_env = kMates;
  c.world.num_boxes = 3;
  c.world.num_cylinders = 2;
  return c;
}

/// `num_envs` 6 x 6 m arenas of generated rooms and clutter, `kMates` scanning robots each.
EnvConfig generatedTeam(int num_envs, int threads = 1) {
  EnvConfig c = test::scanningArenaConfig(num_envs, threads);
  c.team.robots_per_env = kMates;
  c.world.arena_size = {6.0, 6.0};
  c.world.num_boxes = 0;
  c.world.num_cylinders = 0;
  c.world.families = {"rooms", "clutter"};
  c.world.difficulty = 0.7;
  return c;
}

/// The placed obstacles of `row`'s layout as numbers, to compare.
std::vector<double> obstaclesOf(const BatchedEnv& env, int row) {
  std::vector<double> out;
  for (const Obstacle& o : env.view(row).layout().obstacles) {
    if (!o.placed) continue;
    out.insert(out.end(), {o.center.x(), o.center.y(), o.yaw, o.radius, o.half_extents.x(),
                           o.half_extents.y()});
  }
  return out;
}

/// Distance from `p` to the nearest placed obstacle's bounding circle of `row`'s layout [m].
double clearanceOf(const BatchedEnv& env, int row, const Eigen::Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Obstacle& o : env.view(row).layout().obstacles) {
    if (o.placed) d = std::min(d, (o.center - p).norm() - o.boundingRadius());
  }
  return d;
}

TEST(TeamObstacles, TheRobotsOfAWorldShareItsObstaclesAndStartAndAimClearOfThem) {
  const int n = 3;
  BatchedEnv env(test::lidarJetbot(), clutteredTeam(n), test::navigationTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  const double clearance = env.world()->startClearance();
  for (int g = 0; g < n; ++g) {
    const std::vector<double> world = obstaclesOf(env, g * kMates);
    EXPECT_GE(world.size(), 6u * 4) << "world " << g << ": most of its 5 obstacles placed";
    if (g > 0) EXPECT_NE(world, obstaclesOf(env, 0)) << "world " << g << " drew its own";
    for (int row = g * kMates; row < (g + 1) * kMates; ++row) {
      EXPECT_EQ(obstaclesOf(env, row), world) << "row " << row;
      const Eigen::Vector2d start = env.view(row).rootState().position.head<2>();
      EXPECT_GE(clearanceOf(env, row, start), clearance - 1e-9) << "row " << row;
      EXPECT_GT(clearanceOf(env, row, task.goal(row)), 0.0) << "row " << row;
    }
  }
}

TEST(TeamObstacles, OneRobotStartsAnewAmongTheOldObstaclesAndAllAmongNewOnes) {
  BatchedEnv env(test::lidarJetbot(), clutteredTeam(2), test::navigationTask());
  const std::vector<double> before = obstaclesOf(env, 0), other = obstaclesOf(env, kMates);
  const Eigen::Vector2d start = env.view(1).rootState().position.head<2>();
  env.reset({1});
  EXPECT_NE(env.view(1).rootState().position.head<2>(), start);
  for (int row = 0; row < 2 * kMates; ++row) {
    EXPECT_EQ(obstaclesOf(env, row), row < kMates ? before : other) << "row " << row;
  }
  env.reset({0, 1, 2});  // world 0 whole: new obstacles there, world 1 as it was
  EXPECT_NE(obstaclesOf(env, 0), before);
  EXPECT_EQ(obstaclesOf(env, 2), obstaclesOf(env, 0));
  EXPECT_EQ(obstaclesOf(env, kMates), other);
}

TEST(TeamObstacles, ARobotOfTheWorldThatDidNotDrawThemHitsThem) {
  BatchedEnv env(test::lidarJetbot(), clutteredTeam(1), test::navigationTask());
  // Robot 2 (its world's obstacles drawn by robot 0's stream) 0.15 m from the nearest one's
  // bounding circle, facing its centre; the others behind it, standing.
  const Obstacle* nearest = nullptr;
  for (const Obstacle& o : env.view(2).layout().obstacles) {
    if (o.placed && (!nearest || o.center.norm() < nearest->center.norm())) nearest = &o;
  }
  ASSERT_TRUE(nearest);
  // From the arena's middle side.
  const Eigen::Vector2d towards = nearest->center.norm() > 1e-6
                                      ? Eigen::Vector2d(-nearest->center.normalized())
                                      : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d at = nearest->center + (nearest->boundingRadius() + 0.15) * towards;
  test::place(env, 2, at, std::atan2(-towards.y(), -towards.x()));
  // The others behind it, 1 m further from the obstacle and 0.4 m to either side.
  const Eigen::Vector2d side(-towards.y(), towards.x());
  test::place(env, 0, at + towards + 0.4 * side, 0.0);
  test::place(env, 1, at + towards - 0.4 * side, 0.0);
  std::vector<float> actions(kMates * env.actionDim(), 0.0f);
  for (int i = 0; i < env.actionDim(); ++i) actions[2 * env.actionDim() + i] = env.actionHigh()[i];
  bool hit = false;
  for (int step = 0; step < 120 && !hit; ++step) {
    const StepResult& r = env.step(actions);
    for (std::size_t k = 0; k < r.reset_env_ids.size(); ++k) {
      if (r.reset_env_ids[k] == 2) {
        ASSERT_EQ(r.outcomes[k], static_cast<std::uint8_t>(Outcome::kCollision)) << "step " << step;
        hit = true;
      }
    }
  }
  EXPECT_TRUE(hit) << "robot 2 drove through its world's obstacle at (" << nearest->center.x()
                   << ", " << nearest->center.y() << ")";
}

TEST(TeamObstacles, InAGeneratedLayoutEachRobotStartsOnItsFreeFloorWithAPathToItsGoal) {
  const int n = 8;
  EnvConfig c = generatedTeam(n);
  c.world.families = {"maze", "rooms"};  // at their hardest: many goals without a path
  c.world.difficulty = 1.0;
  c.world.start_clearance = 0.3;  // config/navigation_env.yaml's: a maze at 1 leaves no 0.4 m
  BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  const WorldModel& world = *env.world();
  for (int g = 0; g < n; ++g) {
    const EnvLayout& layout = env.view(g * kMates).layout();
    ASSERT_FALSE(layout.unmade) << "world " << g;
    EXPECT_GE(layout.obstacles.size(), 4u) << "world " << g << ": walls or clutter";
    const FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(),
                             layout.obstacles);
    for (int row = g * kMates; row < (g + 1) * kMates; ++row) {
      EXPECT_EQ(obstaclesOf(env, row), obstaclesOf(env, g * kMates)) << "row " << row;
      EXPECT_EQ(env.view(row).layout().family, layout.family) << "row " << row;
      const Eigen::Vector2d start = env.view(row).rootState().position.head<2>();
      EXPECT_TRUE(fitsGeneratedStart(world, grid, layout.obstacles, start)) << "row " << row;
      for (int mate = g * kMates; mate < row; ++mate) {
        EXPECT_GE((env.view(mate).rootState().position.head<2>() - start).norm(),
                  world.startClearance())
            << "rows " << mate << " and " << row;
      }
      FootprintGrid reach = grid;
      ASSERT_TRUE(reach.reachFrom(start)) << "row " << row;
      EXPECT_TRUE(reach.reachable(task.goal(row))) << "row " << row << ": no path to its goal";
    }
  }
  EXPECT_EQ(env.layoutsUnmade(), 0u);
}

TEST(TeamObstacles, OneRobotStartsAnewInTheOldLayoutAndAllInANewOne) {
  BatchedEnv env(test::lidarJetbot(), generatedTeam(2), test::navigationTask());
  const std::vector<double> before = obstaclesOf(env, 0), other = obstaclesOf(env, kMates);
  env.reset({1});
  for (int row = 0; row < 2 * kMates; ++row) {
    EXPECT_EQ(obstaclesOf(env, row), row < kMates ? before : other) << "row " << row;
  }
  env.reset({0, 1, 2});
  EXPECT_NE(obstaclesOf(env, 0), before);
  EXPECT_EQ(obstaclesOf(env, 1), obstaclesOf(env, 0));
  EXPECT_EQ(obstaclesOf(env, kMates), other);
}

TEST(TeamObstacles, TheSameOnAnyThreadCountWithRoundsAndPeople) {
  const auto run = [](bool generated, int threads, bool rounds) {
    EnvConfig c = generated ? generatedTeam(4, threads) : clutteredTeam(4, threads);
    c.team.rounds = rounds;
    c.movers.num_people = 2;
    BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
    Rng rng(5);
    std::vector<float> out, actions(env.numEnvs() * env.actionDim());
    env.reset({}, 13);
    for (int step = 0; step < 300; ++step) {
      for (std::size_t i = 0; i < actions.size(); ++i) {
        actions[i] = static_cast<float>(env.actionHigh()[i % env.actionDim()] * rng.uniform());
      }
      const StepResult& r = env.step(actions);
      out.insert(out.end(), r.observations.begin(), r.observations.end());
      out.insert(out.end(), r.outcomes.begin(), r.outcomes.end());
    }
    const std::vector<double> obstacles = obstaclesOf(env, 0);
    out.insert(out.end(), obstacles.begin(), obstacles.end());
    return out;
  };
  for (bool generated : {false, true}) {
    for (bool rounds : {false, true}) {
      const std::vector<float> one = run(generated, 1, rounds), two = run(generated, 2, rounds);
      ASSERT_EQ(one.size(), two.size());
      EXPECT_TRUE(std::equal(one.begin(), one.end(), two.begin()))
          << "1 and 2 threads differ, generated " << generated << ", rounds " << rounds;
    }
  }
}

}  // namespace
}  // namespace jetbot_rl
