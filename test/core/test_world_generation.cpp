// Generated worlds (issue 30): clutter, rooms and mazes drawn per env at every reset from the
// env's own stream; every start and goal joined by a path for the robot (checked here on a finer
// grid than the generator's), the clutter's narrowest passage kept, families mixed by weight,
// a layout that cannot be made counted and flagged, the curriculum and its mix, the same layouts on
// any thread count, and bad parameters refused naming the field.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <deque>
#include <map>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/scene/curriculum.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/world/world_generation.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

EnvConfig generatedConfig(int envs, int threads, std::vector<std::string> families) {
  EnvConfig c = test::scanningArenaConfig(envs, threads);
  c.episode_length_s = 0.05;  // 3 control steps: a new layout every few steps
  c.world.start_clearance = 0.3;
  c.world.families = std::move(families);
  return c;
}

/// An oracle independent of FootprintGrid: a 4-connected walk over 0.02 m cells whose centres
/// keep more than `radius` from every wall and placed obstacle (exact distances).
bool hasPath(const WorldModel& world, const std::vector<Obstacle>& obstacles, double radius,
             const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  constexpr double kCell = 0.02;
  const Eigen::AlignedBox2d area = world.region();
  const int w = static_cast<int>(area.sizes().x() / kCell),
            h = static_cast<int>(area.sizes().y() / kCell);
  std::vector<std::uint8_t> free(static_cast<std::size_t>(w) * h, 1), seen(free.size(), 0);
  const auto centre = [&](int x, int y) {
    return Eigen::Vector2d(area.min() + kCell * Eigen::Vector2d(x + 0.5, y + 0.5));
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (world.staticClearance(centre(x, y)) <= radius) free[y * w + x] = 0;
    }
  }
  for (const Obstacle& o : obstacles) {
    if (!o.placed) continue;
    // The cells of the obstacle's bounding square grown by the footprint.
    const double reach = o.boundingRadius() + radius + kCell;
    const Eigen::Vector2d lo = (o.center - area.min()).array() / kCell - reach / kCell;
    const Eigen::Vector2d hi = (o.center - area.min()).array() / kCell + reach / kCell;
    for (int y = std::max(0, static_cast<int>(lo.y())); y < std::min(h, int(hi.y()) + 1); ++y) {
      for (int x = std::max(0, static_cast<int>(lo.x())); x < std::min(w, int(hi.x()) + 1); ++x) {
        const Eigen::Vector2d c = centre(x, y);
        if ((c - o.center).norm() > reach) continue;
        if (o.distance(c) <= radius) free[y * w + x] = 0;
      }
    }
  }
  const auto cell = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d q = (p - area.min()) / kCell;
    return static_cast<int>(q.y()) * w + static_cast<int>(q.x());
  };
  // Start and goal keep more than the footprint from everything, so their own cells are free.
  std::deque<int> queue{cell(from)};
  if (!free[queue.front()]) return false;
  seen[queue.front()] = 1;
  while (!queue.empty()) {
    const int c = queue.front();
    queue.pop_front();
    if (c == cell(to)) return true;
    const int x = c % w, y = c / w;
    for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      if (x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h) continue;
      const int n = (y + dy) * w + x + dx;
      if (free[n] && !seen[n]) {
        seen[n] = 1;
        queue.push_back(n);
      }
    }
  }
  return false;
}

TEST(GeneratedWorlds, EveryStartAndGoalHaveAPathForTheRobotsFootprint) {
  for (const char* family : {"clutter", "rooms", "maze", "barn"}) {
    for (double difficulty : {0.0, 1.0}) {
      EnvConfig c = generatedConfig(4, 2, {family});
      c.world.max_generated_obstacles = 2000;
      c.world.difficulty = difficulty;
      BatchedEnv env(test::jetbot(), c, test::navigationTask());
      const auto& task = dynamic_cast<const NavigationTask&>(env.task());
      const double radius = env.world()->robotRadius();
      int checked = 0;
      for (int s = 0; s < 12; ++s) {
        for (int e : env.step(test::seededActions(4, 500 + s)).reset_env_ids) {
          const EnvLayout& l = env.view(e).layout();
          ASSERT_FALSE(l.unmade) << family << " env " << e;
          EXPECT_EQ(l.family, 0);
          EXPECT_EQ(l.difficulty, difficulty);
          EXPECT_GE(env.world()->clearance(l.start, &l.obstacles), c.world.start_clearance)
              << family << " env " << e;
          const Eigen::Vector2d goal = task.goal(e);
          EXPECT_TRUE(env.world()->region().contains(goal));
          EXPECT_GE(env.world()->clearance(goal, &l.obstacles), 0.3) << family << " env " << e;
          EXPECT_TRUE(hasPath(*env.world(), l.obstacles, radius, l.start, goal))
              << family << " at " << difficulty << ", env " << e << ": start "
              << l.start.transpose() << ", goal " << goal.transpose();
          ++checked;
        }
      }
      EXPECT_GE(checked, 12) << family;
    }
  }
}

TEST(GeneratedWorlds, ClutterKeepsItsNarrowestPassageAndGrowsDenserWithDifficulty) {
  GenerationArea area;
  area.area = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  area.robot_radius = 0.1;
  std::map<double, double> mean_count;
  for (double d : {0.0, 0.5, 1.0}) {
    const double passage = narrowestPassage(area, d);
    EXPECT_NEAR(passage, (4.0 - 2.5 * d) * 0.2, 1e-12);
    int total = 0;
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      Rng rng(7, seed);
      std::vector<Obstacle> out;
      ASSERT_EQ(generateObstacles(WorldFamily::kClutter, d, area, rng, 1000, out), 0);
      total += static_cast<int>(out.size());
      for (std::size_t i = 0; i < out.size(); ++i) {
        const Obstacle& a = out[i];
        // Half a passage from the area's edges, a whole one from each other.
        EXPECT_TRUE(area.area.contains(a.center));
        EXPECT_GE((a.center - area.area.min()).minCoeff() - a.boundingRadius(),
                  0.5 * passage - 1e-9);
        EXPECT_GE((area.area.max() - a.center).minCoeff() - a.boundingRadius(),
                  0.5 * passage - 1e-9);
        for (std::size_t j = i + 1; j < out.size(); ++j) {
          ASSERT_GE(
              (a.center - out[j].center).norm() - a.boundingRadius() - out[j].boundingRadius(),
              passage - 1e-9)
              << "difficulty " << d << " seed " << seed << " obstacles " << i << ", " << j;
        }
      }
    }
    mean_count[d] = total / 20.0;
  }
  EXPECT_GT(mean_count[0.5], mean_count[0.0]);
  EXPECT_GT(mean_count[1.0], mean_count[0.5]);
  EXPECT_GT(mean_count[1.0], 100.0);  // hundreds of obstacles in 10 x 10 m
  // world/passage_widths moves the narrowest passage: 1.05 widths at 1, 2 at 0.
  area.passage_widths_hard = 1.05;
  area.passage_widths_easy = 2.0;
  EXPECT_NEAR(narrowestPassage(area, 1.0), 1.05 * 0.2, 1e-12);
  EXPECT_NEAR(narrowestPassage(area, 0.5), 1.525 * 0.2, 1e-12);
  Rng rng(7, 1);
  std::vector<Obstacle> out;
  generateObstacles(WorldFamily::kClutter, 1.0, area, rng, 1000, out);
  double narrowest = 1e9;
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (std::size_t j = i + 1; j < out.size(); ++j) {
      narrowest = std::min(narrowest, (out[i].center - out[j].center).norm() -
                                          out[i].boundingRadius() - out[j].boundingRadius());
    }
  }
  EXPECT_GE(narrowest, 1.05 * 0.2 - 1e-9);
  EXPECT_LT(narrowest, 1.5 * 0.2);  // closer than the default's hardest allows
}

TEST(GeneratedWorlds, RoomsHaveDoorsAndMazesSmallerCellsWithDifficulty) {
  GenerationArea area;
  area.area = Eigen::AlignedBox2d(Eigen::Vector2d(-2, -2), Eigen::Vector2d(2, 2));
  area.robot_radius = 0.1;
  for (WorldFamily f : {WorldFamily::kRooms, WorldFamily::kMaze}) {
    std::vector<Obstacle> easy, hard;
    Rng a(1, 0), b(1, 0);
    generateObstacles(f, 0.0, area, a, 1000, easy);
    generateObstacles(f, 1.0, area, b, 1000, hard);
    EXPECT_GT(hard.size(), easy.size()) << enumName(f);
    if (f != WorldFamily::kMaze) continue;
    for (const Obstacle& o : hard) {  // walls along the axes
      EXPECT_EQ(o.shape, Obstacle::Shape::kBox);
      EXPECT_EQ(o.yaw, 0.0);
    }
  }
  // A wall between two rooms: two pieces either side of a door at least a passage wide.
  std::vector<Obstacle> walls;
  Rng rng(3, 0);
  generateObstacles(WorldFamily::kRooms, 0.0, area, rng, 1000, walls);
  ASSERT_EQ(walls.size(), 8u);  // 2 x 2 rooms: 4 wall segments between them, each cut by a door
  for (std::size_t k = 0; k < walls.size(); k += 2) {
    const double length = 2.0 * (walls[k].half_extents.x() + walls[k + 1].half_extents.x());
    EXPECT_LE(length, 2.0 - narrowestPassage(area, 0.0) + 1e-9);
  }
}

TEST(GeneratedWorlds, ObstaclesBeyondTheSlotsAreLeftOutAndCounted) {
  GenerationArea area;
  area.area = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  std::vector<Obstacle> out;
  Rng rng(2, 0);
  const int left_out = generateObstacles(WorldFamily::kClutter, 1.0, area, rng, 10, out);
  EXPECT_EQ(out.size(), 10u);
  EXPECT_GT(left_out, 50);

  EnvConfig c = generatedConfig(2, 1, {"clutter"});
  c.world.difficulty = 1.0;
  c.world.max_generated_obstacles = 5;
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  EXPECT_GT(env.obstaclesGivenUp(), 0u);
  EXPECT_LE(env.view(0).layout().obstacles.size(), 5u);
}

TEST(GeneratedWorlds, FamiliesAreDrawnByTheirWeights) {
  EnvConfig c = generatedConfig(8, 2, {"clutter", "rooms", "maze"});
  c.world.family_weights = {1.0, 0.0, 3.0};
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  std::array<int, 3> count{};
  for (int s = 0; s < 60; ++s) {
    for (int e : env.step(test::seededActions(8, 500 + s)).reset_env_ids)
      ++count[env.view(e).layout().family];
  }
  EXPECT_EQ(count[1], 0);
  const double share = count[2] / static_cast<double>(count[0] + count[2]);
  EXPECT_NEAR(share, 0.75, 0.08) << count[0] << " clutter, " << count[2] << " mazes";
}

TEST(GeneratedWorlds, SameSeedSameLayoutsGoalsAndScansOnAnyThreadCount) {
  const auto config = [](int threads) {
    EnvConfig c = generatedConfig(10, threads, {"clutter", "rooms", "maze"});
    c.world.difficulty = 0.7;
    return c;
  };
  BatchedEnv one(test::jetbot(), config(1), test::navigationTask());
  BatchedEnv two(test::jetbot(), config(2), test::navigationTask());
  BatchedEnv three(test::jetbot(), config(3), test::navigationTask());
  const auto& ta = dynamic_cast<const NavigationTask&>(one.task());
  const auto& tb = dynamic_cast<const NavigationTask&>(three.task());
  for (int s = 0; s < 40; ++s) {
    const StepResult& a = one.step(test::seededActions(10, 500 + s));
    ASSERT_EQ(a.observations, two.step(test::seededActions(10, 500 + s)).observations)
        << "step " << s;
    ASSERT_EQ(a.observations, three.step(test::seededActions(10, 500 + s)).observations)
        << "step " << s;
    for (int e = 0; e < 10; ++e) {
      const EnvLayout& la = one.view(e).layout();
      const EnvLayout& lb = three.view(e).layout();
      ASSERT_EQ(la.start, lb.start);
      ASSERT_EQ(la.family, lb.family);
      ASSERT_EQ(ta.goal(e), tb.goal(e));
      ASSERT_EQ(la.obstacles.size(), lb.obstacles.size());
      for (std::size_t k = 0; k < la.obstacles.size(); ++k) {
        ASSERT_EQ(la.obstacles[k].center, lb.obstacles[k].center);
        ASSERT_EQ(la.obstacles[k].half_extents, lb.obstacles[k].half_extents);
        ASSERT_EQ(la.obstacles[k].radius, lb.obstacles[k].radius);
      }
      ASSERT_EQ(std::memcmp(one.view(e).scan(), three.view(e).scan(), 24 * sizeof(float)), 0);
    }
  }
}

TEST(GeneratedWorlds, ALayoutThatCannotBeMadeIsCountedAndRunsInTheBareArena) {
  EnvConfig c = generatedConfig(3, 1, {"maze"});
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  t.navigation.goal_distance = {6.0, 7.0};  // never inside the 4 x 4 m arena
  BatchedEnv env(test::jetbot(), c, makeTask(t));
  EXPECT_EQ(env.layoutsUnmade(), 3u);  // the first reset of each env
  for (int e = 0; e < 3; ++e) {
    EXPECT_TRUE(env.view(e).layout().unmade);
    EXPECT_TRUE(env.view(e).layout().obstacles.empty());
  }
  const std::uint64_t before = env.layoutsUnmade();
  std::vector<float> observations;
  for (int s = 0; s < 6; ++s) observations = env.step(test::seededActions(3, 500 + s)).observations;
  EXPECT_GT(env.layoutsUnmade(), before);
  for (float x : observations) EXPECT_TRUE(std::isfinite(x));

  // The same world with goals that fit: none unmade.
  BatchedEnv fine(test::jetbot(), c, test::navigationTask());
  for (int s = 0; s < 6; ++s) fine.step(test::seededActions(3, 500 + s));
  EXPECT_EQ(fine.layoutsUnmade(), 0u);
}

TEST(GeneratedWorlds, TheCurriculumRaisesAnEnvsDifficultyAfterAGoodRun) {
  WorldConfig w;
  w.curriculum = true;
  w.difficulty = 0.2;
  w.curriculum_episodes = 4;
  w.curriculum_success = 0.75;
  w.curriculum_step = 0.3;
  Curriculum curriculum(w, 2);
  for (bool s : {true, true, false, true}) curriculum.episodeEnded(0, s);   // 3 of 4: raised
  for (bool s : {true, false, false, true}) curriculum.episodeEnded(1, s);  // 2 of 4: kept
  EXPECT_DOUBLE_EQ(curriculum.difficulty(0), 0.5);
  EXPECT_DOUBLE_EQ(curriculum.difficulty(1), 0.2);
  for (int k = 0; k < 3; ++k) curriculum.episodeEnded(0, true);  // a run not yet complete
  EXPECT_DOUBLE_EQ(curriculum.difficulty(0), 0.5);
  curriculum.episodeEnded(0, true);
  for (int k = 0; k < 8; ++k) curriculum.episodeEnded(0, true);
  EXPECT_DOUBLE_EQ(curriculum.difficulty(0), 1.0);  // capped
  w.curriculum = false;
  Curriculum off(w, 1);
  for (int k = 0; k < 8; ++k) off.episodeEnded(0, true);
  EXPECT_DOUBLE_EQ(off.difficulty(0), 0.2);

  // In the batch: with curriculum_success 0 every run of 2 episodes raises it, and the layouts
  // are drawn at each env's own difficulty.
  EnvConfig c = generatedConfig(4, 2, {"clutter"});
  c.world.difficulty = 0.0;
  c.world.curriculum = true;
  c.world.curriculum_episodes = 2;
  c.world.curriculum_success = 0.0;
  c.world.curriculum_step = 0.25;
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  std::vector<int> episodes(4, 0);
  for (int s = 0; s < 20; ++s) {
    for (int e : env.step(test::seededActions(4, 500 + s)).reset_env_ids) {
      ++episodes[e];
      EXPECT_DOUBLE_EQ(env.view(e).layout().difficulty, env.difficulty(e));
    }
  }
  for (int e = 0; e < 4; ++e) {
    EXPECT_DOUBLE_EQ(env.difficulty(e), std::min(1.0, 0.25 * (episodes[e] / 2))) << "env " << e;
  }
}

TEST(GeneratedWorlds, TheCurriculumMixDrawsItsShareOfLayoutsBelowAnEnvsDifficulty) {
  WorldConfig w;
  w.curriculum = true;
  w.difficulty = 0.8;
  w.curriculum_mix = 0.25;
  const Curriculum mixed(w, 1);
  Rng rng(7, 0);
  int below = 0;
  double sum_below = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double d = mixed.drawDifficulty(0, rng);
    ASSERT_GE(d, 0.0);
    ASSERT_LE(d, 0.8);
    if (d < 0.8) {
      ++below;
      sum_below += d;
    }
  }
  EXPECT_NEAR(below / 4000.0, 0.25, 0.03);
  EXPECT_NEAR(sum_below / below, 0.4, 0.04);  // uniform in [0, 0.8]
  // Without the mix, or without the curriculum, the env's own difficulty and nothing drawn
  // from its stream (the layouts stay those of runs without the parameter).
  for (const auto& [curriculum, mix] : {std::pair{true, 0.0}, std::pair{false, 0.5}}) {
    w.curriculum = curriculum;
    w.curriculum_mix = mix;
    Rng a(7, 0), b(7, 0);
    for (int k = 0; k < 100; ++k) ASSERT_DOUBLE_EQ(Curriculum(w, 1).drawDifficulty(0, a), 0.8);
    EXPECT_EQ(a.next(), b.next());
  }

  // In the batch: the layouts are drawn at the env's difficulty or below it, some below.
  EnvConfig c = generatedConfig(4, 2, {"clutter"});
  c.world.difficulty = 0.9;
  c.world.curriculum = true;
  c.world.curriculum_success = 1.0;
  c.world.curriculum_mix = 0.5;
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  int layouts = 0, easier = 0;
  for (int s = 0; s < 40; ++s) {
    for (int e : env.step(test::seededActions(4, 500 + s)).reset_env_ids) {
      ++layouts;
      EXPECT_LE(env.view(e).layout().difficulty, env.difficulty(e));
      easier += env.view(e).layout().difficulty < env.difficulty(e) ? 1 : 0;
    }
  }
  EXPECT_GT(easier, layouts / 4) << easier << " of " << layouts;
  EXPECT_LT(easier, 3 * layouts / 4) << easier << " of " << layouts;
}

TEST(GeneratedWorlds, BadParametersAreRefusedNamingTheField) {
  const EnvConfig good = generatedConfig(1, 1, {"clutter", "maze"});
  EnvConfig c = good;
  c.world.families = {"clutter", "forest"};
  test::expectRefused(test::jetbot(), c, "world/families");
  c = good;
  c.world.family_weights = {1.0};
  test::expectRefused(test::jetbot(), c, "world/family_weights = [1]");
  c.world.family_weights = {0.0, 0.0};
  test::expectRefused(test::jetbot(), c, "world/family_weights");
  c.world.family_weights = {1.0, -1.0};
  test::expectRefused(test::jetbot(), c, "world/family_weights");
  c = good;
  c.world.arena_size = {};
  c.world.region = {-1, -1, 1, 1};
  test::expectRefused(test::jetbot(), c, "world/families");
  c = good;
  c.world.region = {-1, -1, 1, 1};
  test::expectRefused(test::jetbot(), c, "world/region");
  c = good;
  c.world.num_cylinders = 3;
  test::expectRefused(test::jetbot(), c, "world/num_cylinders = 3");
  c = good;
  c.world.difficulty = 1.5;
  test::expectRefused(test::jetbot(), c, "world/difficulty = 1.5");
  c = good;
  c.world.max_generated_obstacles = 0;
  test::expectRefused(test::jetbot(), c, "world/max_generated_obstacles = 0");
  c = good;
  c.world.passage_widths = {1.0, 4.0};  // the robot would touch both sides
  test::expectRefused(test::jetbot(), c, "world/passage_widths = [1, 4]");
  c.world.passage_widths = {4.0, 1.5};  // harder at 0 than at 1
  test::expectRefused(test::jetbot(), c, "world/passage_widths = [4, 1.5]");
  c.world.passage_widths = {1.5};
  test::expectRefused(test::jetbot(), c, "world/passage_widths = [1.5]");
  c = good;
  c.world.curriculum_mix = 1.5;
  test::expectRefused(test::jetbot(), c, "world/curriculum_mix = 1.5");
  c = good;
  c.world.families = {};
  c.world.num_boxes = 2;
  c.world.curriculum = true;
  test::expectRefused(test::jetbot(), c, "world/curriculum = true");
  // A maze too tight for any start with this clearance, at the difficulty the curriculum reaches.
  c = good;
  c.world.families = {"maze"};
  c.world.arena_size = {1.5, 1.5};  // one 1.5 m cell at 0, four of 0.75 m at 1
  c.world.start_clearance = 0.5;
  c.world.difficulty = 1.0;
  test::expectRefused(test::jetbot(), c, "world/difficulty = 1");
  c.world.difficulty = 0.0;
  EXPECT_NO_THROW(BatchedEnv(test::jetbot(), c, test::navigationTask()));
  c.world.curriculum = true;
  test::expectRefused(test::jetbot(), c, "world/difficulty = 1");
}

}  // namespace
}  // namespace jetbot_rl
