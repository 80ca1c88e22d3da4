// The command-following task: observation and reward variants on hand-computed states, and the
// command draw (unit, in the plane, reproducible per seed, redrawn only on reset).
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/tasks/command_task.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

/// A robot yawed by `yaw` [rad] moving at `speed` [m/s] along its own x axis.
RootState yawedState(double yaw, double speed) {
  RootState s;
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  s.com_linear_velocity = s.orientation * Eigen::Vector3d(speed, 0, 0);
  return s;
}

TEST(CommandTask, ObservationOnHandComputedStates) {
  CommandTask task;
  task.resize(1);
  task.setCommand(0, Eigen::Vector2d(0, 2));  // +y, normalised to unit length
  float obs[3];
  // Facing +x, command +y: 90 degrees to the left.
  task.observe(0, yawedState(0.0, 0.25), obs);
  EXPECT_NEAR(obs[0], 0.0, 1e-6);
  EXPECT_NEAR(obs[1], 1.0, 1e-6);
  EXPECT_NEAR(obs[2], 0.25, 1e-6);
  // Facing 30 degrees, command at 90: the command is 60 degrees to the left.
  task.observe(0, yawedState(M_PI / 6, -0.1), obs);
  EXPECT_NEAR(obs[0], 0.5, 1e-6);
  EXPECT_NEAR(obs[1], std::sqrt(3.0) / 2, 1e-6);
  EXPECT_NEAR(obs[2], -0.1, 1e-6);
  // Facing 180 degrees: the command is 90 degrees to the right.
  task.observe(0, yawedState(M_PI, 0.0), obs);
  EXPECT_NEAR(obs[1], -1.0, 1e-6);
}

TEST(CommandTask, EveryRewardVariant) {
  const RootState s = yawedState(M_PI / 3, 0.4);  // dot with +x command = 0.5
  const double dot = 0.5, v = 0.4;
  for (auto [variant, expected] : {std::pair{CommandTask::Variant::kExp, v * std::exp(dot)},
                                   std::pair{CommandTask::Variant::kSum, v + dot},
                                   std::pair{CommandTask::Variant::kProduct, v * dot}}) {
    CommandTask task(variant);
    task.resize(1);
    task.setCommand(0, Eigen::Vector2d(1, 0));
    EXPECT_NEAR(task.reward(0, s), expected, 1e-6) << enumName(variant);
  }
  // The product variant rewards reversing away from the command; exp does not.
  const RootState reversing = yawedState(M_PI, -0.4);  // facing away, moving towards +x
  CommandTask product(CommandTask::Variant::kProduct), exp_task;
  product.resize(1);
  exp_task.resize(1);
  product.setCommand(0, Eigen::Vector2d(1, 0));
  exp_task.setCommand(0, Eigen::Vector2d(1, 0));
  EXPECT_GT(product.reward(0, reversing), 0.0f);
  EXPECT_LT(exp_task.reward(0, reversing), 0.0f);
}

TEST(CommandTask, VariantNamesRoundTripAndBadOnesAreNamed) {
  for (auto v :
       {CommandTask::Variant::kExp, CommandTask::Variant::kSum, CommandTask::Variant::kProduct}) {
    EXPECT_EQ(parseEnum<CommandTask::Variant>("reward_variant", enumName(v)), v);
  }
  try {
    parseEnum<CommandTask::Variant>("reward_variant", "max");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("reward_variant = 'max'"), std::string::npos) << e.what();
  }
}

TEST(CommandTask, CommandsAreUnitPlanarReproducibleAndRedrawnOnlyOnReset) {
  auto make = [](std::uint64_t seed) {
    EnvConfig c = smallConfig(8);
    c.seed = seed;
    return std::make_unique<BatchedEnv>(jetbot(), c, std::make_unique<CommandTask>());
  };
  auto a = make(5), b = make(5), other = make(6);
  auto commands = [](BatchedEnv& env) {
    std::vector<Eigen::Vector2d> out;
    for (int e = 0; e < env.numEnvs(); ++e)
      out.push_back(static_cast<CommandTask&>(env.task()).command(e));
    return out;
  };
  const auto first = commands(*a);
  EXPECT_EQ(first, commands(*b));
  EXPECT_NE(first, commands(*other));
  for (const auto& c : first) EXPECT_NEAR(c.norm(), 1.0, 1e-12);
  for (size_t i = 1; i < first.size(); ++i) EXPECT_NE(first[i], first[0]);  // independent envs
  // Stepping does not redraw; an env's reset does, and only its own.
  for (int s = 0; s < 20; ++s) a->step(randomActions(8, s));
  EXPECT_EQ(commands(*a), first);
  a->reset({3});
  const auto after = commands(*a);
  for (int e = 0; e < 8; ++e) {
    if (e == 3) {
      EXPECT_NE(after[e], first[e]);
    } else {
      EXPECT_EQ(after[e], first[e]);
    }
  }
  // Reseeding replays the draw of a fresh env with that seed.
  a->reset({}, 6);
  EXPECT_EQ(commands(*a), commands(*other));
}

TEST(CommandTask, SetCommandRejectsBadInput) {
  CommandTask task;
  task.resize(2);
  EXPECT_THROW(task.setCommand(2, Eigen::Vector2d(1, 0)), InputError);
  EXPECT_THROW(task.setCommand(0, Eigen::Vector2d(0, 0)), InputError);
  EXPECT_THROW(task.setCommand(0, Eigen::Vector2d(NAN, 1)), InputError);
  EXPECT_EQ(task.command(0), Eigen::Vector2d::UnitX());
}

TEST(CommandTask, ObservationsFollowTheRobotInTheBatch) {
  EnvConfig c = smallConfig(1);
  BatchedEnv env(jetbot(), c, std::make_unique<CommandTask>());
  auto& task = static_cast<CommandTask&>(env.task());
  task.setCommand(0, Eigen::Vector2d(1, 0));
  for (int s = 0; s < 60; ++s) env.step({10.0f, 10.0f});
  const auto& obs = env.state().observations;
  EXPECT_NEAR(obs[0], 1.0, 0.01);  // facing the command
  EXPECT_NEAR(obs[2], 0.3, 0.015);
  EXPECT_NEAR(env.state().rewards[0], 0.3 * std::exp(1.0), 0.05);
}

}  // namespace
}  // namespace jetbot_rl

#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace {

TEST(TaskFactory, BuildsEveryTaskByNameAndNamesBadOnes) {
  for (const auto& [kind, name] : enumNames(TaskKind{})) {
    TaskConfig config;
    fieldsFromYaml(std::string("task: ") + name, config);
    EXPECT_EQ(config.task, kind);
    EXPECT_EQ(makeTask(config)->name(), name);
  }
  TaskConfig config;
  fieldsFromYaml("task: command\nreward_variant: sum", config);
  EXPECT_EQ(static_cast<CommandTask&>(*makeTask(config)).variant(), CommandTask::Variant::kSum);
  try {
    fieldsFromYaml("task: maze", config);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "task = 'maze': must be velocity, command, navigation or road_following"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(fieldsFromYaml("reward_variant: max", config), ConfigError);
}

}  // namespace
}  // namespace jetbot_rl

namespace jetbot_rl {
namespace {

TEST(CommandTask, AHeldCommandSurvivesResetsWithoutShiftingTheRandomStream) {
  EnvConfig c = test::smallConfig(2);
  BatchedEnv held(test::jetbot(), c, std::make_unique<CommandTask>());
  BatchedEnv free(test::jetbot(), c, std::make_unique<CommandTask>());
  auto& task = static_cast<CommandTask&>(held.task());
  task.setCommand(0, Eigen::Vector2d(0, -3), /*hold=*/true);
  held.reset();
  free.reset();
  EXPECT_EQ(task.command(0), Eigen::Vector2d(0, -1));
  EXPECT_TRUE(task.held(0));
  EXPECT_EQ(task.command(1), static_cast<CommandTask&>(free.task()).command(1));
  task.setCommand(0, Eigen::Vector2d(1, 0), /*hold=*/false);  // released: the next reset draws
  held.reset();
  free.reset();
  EXPECT_EQ(task.command(0), static_cast<CommandTask&>(free.task()).command(0));
}

}  // namespace
}  // namespace jetbot_rl
