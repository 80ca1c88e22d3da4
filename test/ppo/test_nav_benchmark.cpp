// The navigation benchmark (jetbot_rl_nav_benchmark): its worlds build, an (untrained) policy's
// episodes are counted with rates that add up, successes drive no shorter than the shortest
// path, and an env without the navigation task or a world is refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/eval/nav_benchmark.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// The env the benchmark's worlds are drawn over: the navigation task's env file.
EnvSetup navigationEnv() {
  EnvSetup setup;
  readEnvSetupFiles({std::string(JETBOT_RL_SOURCE_DIR) + "/config/navigation_env.yaml"}, setup);
  return setup;
}

/// A world of the benchmark with `envs` envs on one thread, its episodes short.
EnvSetup benchmarkSetup(const BenchmarkWorld& world, int envs) {
  EnvSetup setup = world.setup;
  setup.env.num_envs = envs;
  setup.env.num_threads = 1;
  setup.env.episode_length_s = 4.0;  // time-outs come soon
  return setup;
}

RobotModelConstPtr lidarJetbot() {
  return RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_lidar.urdf");
}

/// An untrained policy for `env`, saved and loaded as the benchmark loads one.
Policy untrainedPolicy(const BatchedEnv& env) {
  torch::manual_seed(3);
  PpoConfig c;
  c.actor_hidden_dims = {16};
  c.critic_hidden_dims = {16};
  c.init_noise_std = 1.0;
  Ppo ppo(env.spec(), c);
  CheckpointMeta meta;
  meta.obs_dim = env.obsDim();
  meta.action_dim = env.actionDim();
  meta.config = c;
  meta.spec = env.spec();
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_nav_benchmark";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "untrained.pt").string();
  saveCheckpoint(path, ppo, meta);
  return Policy(path);
}

TEST(NavBenchmark, EveryWorldBuildsAndNamesItself) {
  const EnvSetup base = navigationEnv();
  // The shipped room's tables and counter, found as Gazebo finds models.
  ::setenv("GAZEBO_MODEL_PATH", (std::string(JETBOT_RL_SOURCE_DIR) + "/models").c_str(), 1);
  const std::string room = std::string(JETBOT_RL_SOURCE_DIR) + "/worlds/furnished_room.world";
  const auto worlds = navigationBenchmarkWorlds(
      base, std::string(JETBOT_RL_SOURCE_DIR) + "/maps/office.yaml", room);
  ASSERT_EQ(worlds.size(), 18u);
  EXPECT_EQ(worlds[0].name, "clutter 0");
  EXPECT_EQ(worlds[8].name, "maze 1");
  EXPECT_EQ(worlds[11].name, "barn 1");
  EXPECT_EQ(worlds[12].name, "clutter 1.3w");
  EXPECT_EQ(worlds[15].name, "rooms 1.05w");
  EXPECT_EQ(worlds[16].name, "map 1-15 m");
  EXPECT_EQ(worlds[17].name, "gazebo 1-6 m");
  for (const BenchmarkWorld& w : worlds) {
    EXPECT_NO_THROW(makeEnv(lidarJetbot(), benchmarkSetup(w, 2))) << w.name;
    // The world's own episode length, over the env's (20 s), and the rest of the env kept.
    EXPECT_DOUBLE_EQ(w.setup.env.episode_length_s, kBenchmarkEpisodeS) << w.name;
    EXPECT_EQ(w.setup.task.task, TaskKind::kNavigation) << w.name;
    EXPECT_EQ(w.setup.env.decimation, base.env.decimation) << w.name;
    EXPECT_EQ(w.setup.task.navigation.log_beams, base.task.navigation.log_beams) << w.name;
    EXPECT_TRUE(w.setup.env.world.random_start) << w.name;
    EXPECT_FALSE(w.setup.env.world.curriculum) << w.name;
  }
  EXPECT_EQ(worlds[4].setup.env.world.families, (std::vector<std::string>{"rooms"}));
  EXPECT_EQ(worlds[4].setup.env.world.difficulty, 0.5);
  EXPECT_EQ(worlds[4].setup.env.world.arena_size, (std::vector<double>{6.0, 6.0}));
  EXPECT_TRUE(worlds[4].setup.env.world.map.empty());
  // BARN's fields keep every post; the tight rows are the hardest layouts at narrower passages.
  EXPECT_GE(worlds[11].setup.env.world.max_generated_obstacles, 4000);
  EXPECT_EQ(worlds[2].setup.env.world.max_generated_obstacles,
            base.env.world.max_generated_obstacles);  // the other families' slots as given
  EXPECT_EQ(worlds[11].setup.env.world.families, (std::vector<std::string>{"barn"}));
  EXPECT_EQ(worlds[13].setup.env.world.families, (std::vector<std::string>{"clutter"}));
  EXPECT_EQ(worlds[13].setup.env.world.difficulty, 1.0);
  EXPECT_EQ(worlds[13].setup.env.world.passage_widths, (std::vector<double>{1.05, 1.05}));
  EXPECT_EQ(worlds[14].setup.env.world.families, (std::vector<std::string>{"rooms"}));
  EXPECT_EQ(worlds[14].setup.env.world.passage_widths, (std::vector<double>{1.3, 1.3}));
  EXPECT_EQ(worlds[3].setup.env.world.passage_widths, (std::vector<double>{1.5, 4.0}));
  // A slower robot gets the time to drive the longest way at 0.75 of its top speed.
  EXPECT_DOUBLE_EQ(benchmarkEpisodeS(0.6), 60.0);
  EXPECT_DOUBLE_EQ(benchmarkEpisodeS(0.264), 27.0 / (0.75 * 0.264));
  EXPECT_DOUBLE_EQ(benchmarkEpisodeS(2.0), 60.0);
  EXPECT_DOUBLE_EQ(benchmarkEpisodeS(0.0), 60.0);
  EXPECT_DOUBLE_EQ(
      navigationBenchmarkWorlds(base, "m.yaml", "", 136.0)[4].setup.env.episode_length_s, 136.0);
  const EnvSetup map = worlds[16].setup;
  EXPECT_TRUE(map.env.world.families.empty());
  EXPECT_TRUE(map.env.world.arena_size.empty());
  EXPECT_EQ(map.env.world.map, std::string(JETBOT_RL_SOURCE_DIR) + "/maps/office.yaml");
  EXPECT_TRUE(map.task.navigation.goal_reachable);
  EXPECT_EQ(map.task.navigation.goal_distance, (std::vector<double>{1.0, 15.0}));
  const EnvSetup gazebo = worlds[17].setup;
  EXPECT_EQ(gazebo.env.world.gazebo_world, room);
  EXPECT_TRUE(gazebo.env.world.map.empty());
  EXPECT_TRUE(gazebo.env.world.region.empty());  // where the robot can drive from its spawn
  EXPECT_TRUE(gazebo.task.navigation.goal_reachable);
  EXPECT_EQ(navigationBenchmarkWorlds(base, "m.yaml", "").size(), 17u);
}

TEST(NavBenchmark, EpisodesAreCountedAndSuccessesDriveNoShorterThanTheShortestPath) {
  const auto worlds = navigationBenchmarkWorlds(navigationEnv(), "unused.yaml", "");
  const std::unique_ptr<BatchedEnv> env = makeEnv(lidarJetbot(), benchmarkSetup(worlds[3], 6));
  Policy policy = untrainedPolicy(*env);
  const BenchmarkResult r = runNavigationBenchmark(policy, *env, 12, 5000, 0.6);
  EXPECT_FALSE(r.steps_ran_out);
  EXPECT_EQ(r.episodes, 12);  // two per env
  EXPECT_NEAR(r.success + r.collision + r.timeout, 1.0, 1e-12);
  if (r.success > 0.0) {
    EXPECT_GT(r.metrics.time_to_goal, 0.0);
    EXPECT_GT(r.metrics.path_ratio, 0.9);
    EXPECT_GT(r.metrics.spl, 0.0);
    EXPECT_LE(r.metrics.spl, r.success);  // each success's share is at most 1
    EXPECT_LE(r.metrics.barn_score, 0.25 * r.success);
  }
  EXPECT_EQ(r.layouts_unmade, 0u);
  // Goals that never fit the arena: every layout unmade, and the result counts them.
  EnvSetup unfit = benchmarkSetup(worlds[3], 2);
  unfit.task.navigation.goal_distance = {9.0, 10.0};
  const std::unique_ptr<BatchedEnv> bare = makeEnv(lidarJetbot(), unfit);
  EXPECT_GE(runNavigationBenchmark(policy, *bare, 4, 5000, 0.6).layouts_unmade, 2u);
  // With a quota the steps cannot meet, the result says so.
  const std::unique_ptr<BatchedEnv> again = makeEnv(lidarJetbot(), benchmarkSetup(worlds[3], 6));
  EXPECT_TRUE(runNavigationBenchmark(policy, *again, 600, 50, 0.6).steps_ran_out);
}

TEST(NavBenchmark, AnEnvWithoutTheNavigationTaskOrAWorldIsRefused) {
  EnvSetup velocity;
  velocity.env.num_envs = 2;
  const std::unique_ptr<BatchedEnv> env = makeEnv(lidarJetbot(), velocity);
  Policy policy = untrainedPolicy(*env);
  try {
    runNavigationBenchmark(policy, *env, 2, 10, 0.6);
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("needs the navigation task in a world (task = velocity)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
