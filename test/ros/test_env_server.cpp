// The env node's lockstep/realtime logic (EnvServer) on message types, without a master.
#include <gtest/gtest.h>

#include <cmath>

#include "jetbot_rl/ros/env_node/env_server.h"

namespace jetbot_rl {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<BatchedEnv> makeEnv(int num_envs, TaskKind task = TaskKind::kVelocity) {
  EnvConfig config;
  config.num_envs = num_envs;
  config.num_threads = 1;
  TaskConfig task_config;
  task_config.task = task;
  return std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(JETBOT_URDF), config,
                                      makeTask(task_config));
}

WheelTargets targets(std::uint64_t step, std::vector<float> velocities) {
  WheelTargets msg;
  msg.step = step;
  msg.velocities = std::move(velocities);
  return msg;
}

TEST(EnvServer, LockstepStepsOnlyTheCurrentStepAndCountsEveryRejection) {
  auto env = makeEnv(2);
  EnvServer server(*env, EnvMode::kLockstep, 0.5);
  const auto now = Clock::now();
  EXPECT_EQ(server.state()->step, 0u);
  EXPECT_TRUE(server.onWheelTargets(targets(0, {5, 5, 5, 5}), now));
  EXPECT_EQ(server.state()->step, 1u);
  EXPECT_EQ(server.counters().steps, 1u);

  const EnvStep::ConstPtr before = server.state();
  EXPECT_FALSE(server.onWheelTargets(targets(0, {5, 5, 5, 5}), now));  // stale
  EXPECT_NE(server.counters().last_rejection.find("stale step 0: the current step is 1"),
            std::string::npos)
      << server.counters().last_rejection;
  EXPECT_FALSE(server.onWheelTargets(targets(7, {5, 5, 5, 5}), now));  // future
  EXPECT_NE(server.counters().last_rejection.find("future step 7"), std::string::npos);
  EXPECT_FALSE(server.onWheelTargets(targets(1, {5, 5, 5}), now));  // wrong size
  EXPECT_NE(server.counters().last_rejection.find("expected 4 values"), std::string::npos);
  EXPECT_FALSE(server.onWheelTargets(targets(1, {5, NAN, 5, 5}), now));
  EXPECT_NE(server.counters().last_rejection.find("not finite"), std::string::npos);
  EXPECT_EQ(server.counters().rejections, 4u);
  // Nothing changed: the same state object, the same step, one step applied.
  EXPECT_EQ(server.state(), before);
  EXPECT_EQ(env->state().step, 1u);
  EXPECT_EQ(server.counters().steps, 1u);
}

TEST(EnvServer, StepServiceAnswersWithTheNewStateOrTheReason) {
  auto env = makeEnv(1);
  EnvServer server(*env, EnvMode::kLockstep, 0.5);
  Step::Request req;
  Step::Response res;
  req.actions = targets(0, {10, 10});
  EXPECT_TRUE(server.onStep(req, res));
  EXPECT_TRUE(res.success);
  EXPECT_EQ(res.state.step, 1u);
  EXPECT_EQ(res.state.observations, server.state()->observations);

  req.actions = targets(0, {10, 10});  // stale now
  EXPECT_FALSE(server.onStep(req, res));
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("stale step 0"), std::string::npos) << res.message;
  EXPECT_EQ(res.state.step, 1u);
  EXPECT_EQ(server.counters().rejections, 1u);
}

TEST(EnvServer, ResetKeepsTheStepCounterAndABadResetChangesNothing) {
  auto env = makeEnv(3);
  EnvServer server(*env, EnvMode::kLockstep, 0.5);
  for (std::uint64_t s = 0; s < 5; ++s)
    server.onWheelTargets(targets(s, std::vector<float>(6, 8)), Clock::now());
  Reset::Request req;
  Reset::Response res;
  req.env_ids = {1, 1};
  req.seed = -1;
  const EnvStep::ConstPtr before = server.state();
  EXPECT_FALSE(server.onReset(req, res));
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("listed twice"), std::string::npos) << res.message;
  EXPECT_EQ(server.state(), before);

  req.env_ids = {2, 0};
  req.episode_steps = {100, 7};  // in env_ids order
  EXPECT_TRUE(server.onReset(req, res));
  EXPECT_EQ(res.state.step, 5u);
  EXPECT_EQ(res.state.episode_steps, (std::vector<std::uint32_t>{7, 5, 100}));
  req.episode_steps = {100, 299};  // an episode that would end before it starts
  EXPECT_FALSE(server.onReset(req, res));
  EXPECT_NE(res.message.find("episode_steps[1] = 299"), std::string::npos) << res.message;
}

TEST(EnvServer, RealtimeTicksWithTheNewestValidTargetsThenBrakes) {
  auto env = makeEnv(1);
  EnvServer server(*env, EnvMode::kRealtime, 0.5);
  const auto t0 = Clock::now();
  EXPECT_FALSE(server.onWheelTargets(targets(123, {20, 20}), t0));  // step ignored, kept
  EXPECT_EQ(server.state()->step, 0u);
  for (int k = 0; k < 30; ++k) server.onTick(t0 + std::chrono::milliseconds(k));
  EXPECT_EQ(server.state()->step, 30u);
  const double driving = env->view(0).dofVelocity(0);
  EXPECT_GT(driving, 15.0);

  // An invalid message is rejected at the next tick; the previous targets stay in force.
  server.onWheelTargets(targets(0, {20}), t0 + std::chrono::milliseconds(40));
  server.onTick(t0 + std::chrono::milliseconds(41));
  EXPECT_EQ(server.counters().rejections, 1u);
  EXPECT_GT(env->view(0).dofVelocity(0), 15.0);

  // Older than action_timeout: the wheels brake to 0.
  for (int k = 0; k < 60; ++k) server.onTick(t0 + std::chrono::milliseconds(600 + k));
  EXPECT_LT(std::abs(env->view(0).dofVelocity(0)), 0.5);

  Step::Request req;
  Step::Response res;
  EXPECT_FALSE(server.onStep(req, res));
  EXPECT_NE(res.message.find("only served in lockstep"), std::string::npos);
}

TEST(EnvServer, CommandsGoToTasksThatTakeThem) {
  auto velocity = makeEnv(1);
  EnvServer velocity_server(*velocity, EnvMode::kLockstep, 0.5);
  SetCommand::Request req;
  SetCommand::Response res;
  req.env_id = 0;
  req.x = 0.0;
  req.y = 2.0;
  velocity_server.onSetCommand(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("has no command"), std::string::npos) << res.message;

  auto command = makeEnv(2, TaskKind::kCommand);
  EnvServer command_server(*command, EnvMode::kLockstep, 0.5);
  command_server.onSetCommand(req, res);
  EXPECT_TRUE(res.success) << res.message;
  EXPECT_NEAR(capability<ArrowDrawing>(command->task())->arrowDirection(0, 0).y(), 1.0, 1e-12);
  req.env_id = 2;
  command_server.onSetCommand(req, res);
  EXPECT_FALSE(res.success);
  EXPECT_NE(res.message.find("env 2 is out of range"), std::string::npos) << res.message;
}

/// A navigation env of `max_obstacles` generated obstacle slots, goals `goal_distance` away.
std::unique_ptr<BatchedEnv> generatedEnv(int max_obstacles, std::vector<double> goal_distance) {
  EnvConfig config;
  config.num_envs = 2;
  config.num_threads = 1;
  config.episode_length_s = 0.05;  // a reset every 3 steps
  config.world.arena_size = {3.0, 3.0};
  config.world.random_start = true;
  config.world.start_clearance = 0.2;
  config.world.families = {"clutter"};
  config.world.difficulty = 1.0;
  config.world.max_generated_obstacles = max_obstacles;
  config.scan.link = "base_link";
  config.scan.samples = 8;
  TaskConfig task;
  task.task = TaskKind::kNavigation;
  task.navigation.beams = 8;
  task.navigation.goal_distance = std::move(goal_distance);
  return std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(JETBOT_URDF), config,
                                      makeTask(task));
}

TEST(EnvServer, CountsObstaclesLeftOutAndUnmadeLayoutsAsTheEnvDoes) {
  auto crowded = generatedEnv(1, {0.5, 1.0});   // the clutter's other obstacles left out
  auto unmade = generatedEnv(400, {5.0, 6.0});  // goals never in the arena: layouts unmade
  EnvServer crowded_server(*crowded, EnvMode::kLockstep, 0.5);
  EnvServer unmade_server(*unmade, EnvMode::kLockstep, 0.5);
  EXPECT_EQ(unmade_server.counters().layouts_unmade, 2u);  // the first resets
  for (std::uint64_t step = 0; step < 6; ++step) {
    ASSERT_TRUE(crowded_server.onWheelTargets(targets(step, {5, 5, 5, 5}), Clock::now()));
    ASSERT_TRUE(unmade_server.onWheelTargets(targets(step, {5, 5, 5, 5}), Clock::now()));
  }
  EXPECT_GT(crowded_server.counters().obstacles_left_out, 10u);
  EXPECT_EQ(crowded_server.counters().obstacles_left_out, crowded->obstaclesGivenUp());
  EXPECT_EQ(crowded_server.counters().layouts_unmade, 0u);
  EXPECT_GT(unmade_server.counters().layouts_unmade, 2u);
  EXPECT_EQ(unmade_server.counters().layouts_unmade, unmade->layoutsUnmade());
}

}  // namespace
}  // namespace jetbot_rl
