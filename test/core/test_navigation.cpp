// The navigation task: its observation and reward on hand-built situations (goal ahead, behind,
// to the side, a wall in front), its terminations and outcomes, goals drawn in free space, and
// the twist action space.
#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "navigation_fixture.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// A robot at (x, y) heading `yaw`, moving forward at `speed` and turning at `yaw_rate`.
RootState at(double x, double y, double yaw, double speed = 0.0, double yaw_rate = 0.0) {
  RootState s;
  s.position = Eigen::Vector3d(x, y, 0.03);
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  s.com_linear_velocity = s.orientation * Eigen::Vector3d(speed, 0, 0);
  s.angular_velocity = Eigen::Vector3d(0, 0, yaw_rate);
  return s;
}

using Fixture = test::NavigationFixture;

TEST(NavigationTask, ObservesBeamsGoalSpeedYawRateAndTheLastAction) {
  Fixture f({2.0, 0.0});
  const std::vector<std::string> names = f.task.observationNames();
  ASSERT_EQ(names.size(), 4u + 5u + 2u);
  EXPECT_EQ(names[4], "goal_distance");
  EXPECT_EQ(names[10], "last_action_1");
  const std::vector<float> o = f.observe(at(0, 0, 0, 0.3, -0.5));
  // Beam i: the smallest of samples 2i and 2i + 1, clamped into the range and divided by
  // range_max (+inf: range_max, -inf: range_min).
  EXPECT_FLOAT_EQ(o[0], 0.25f);
  EXPECT_FLOAT_EQ(o[1], 1.0f);
  EXPECT_FLOAT_EQ(o[2], 0.025f);
  EXPECT_FLOAT_EQ(o[3], 0.5f);
  f.scan[7] = 1.0f;  // nearer than beam 3's first sample: the sector reads it
  f.sense(false);
  EXPECT_FLOAT_EQ(f.observe(at(0, 0, 0, 0.3, -0.5))[3], 0.25f);
  f.scan[7] = 9.0f;
  f.sense(false);
  EXPECT_NEAR(o[4], 2.0, 1e-6);  // straight ahead: distance 2, angle 0
  EXPECT_NEAR(o[5], 1.0, 1e-6);
  EXPECT_NEAR(o[6], 0.0, 1e-6);
  EXPECT_NEAR(o[7], 0.3, 1e-6);
  EXPECT_NEAR(o[8], -0.5, 1e-6);
  EXPECT_EQ(o[9], 3.0f);
  EXPECT_EQ(o[10], -2.0f);
  // Behind: angle pi.
  std::vector<float> b = f.observe(at(3.0, 0, 0));
  EXPECT_NEAR(b[4], 1.0, 1e-6);
  EXPECT_NEAR(b[5], -1.0, 1e-6);
  EXPECT_NEAR(b[6], 0.0, 1e-6);
  // A robot heading -x, the goal 1.5 m on its -y side: 90 degrees to its left.
  b = f.observe(at(2.0, 1.5, kPi));
  EXPECT_NEAR(b[4], 1.5, 1e-6);
  EXPECT_NEAR(b[5], 0.0, 1e-6);
  EXPECT_NEAR(b[6], 1.0, 1e-6);
}

TEST(NavigationTask, RewardsProgressAndEndsOnTheGoalOrACollision) {
  NavigationConfig config;
  config.proximity_penalty = 0.0;  // the proximity cost has its own test
  Fixture f({2.0, 0.0}, config);
  // After resetEnv the progress reference is the start's distance; set it by a first step.
  EXPECT_FALSE(f.task.terminated(0, at(0, 0, 0)));
  f.task.reward(0, at(0, 0, 0));  // reference: 2 m
  EXPECT_FALSE(f.task.terminated(0, at(0.1, 0, 0)));
  EXPECT_NEAR(f.task.reward(0, at(0.1, 0, 0)), 10.0 * 0.1 - 0.01, 1e-5);
  EXPECT_NEAR(f.task.reward(0, at(0.0, 0, 0)), -10.0 * 0.1 - 0.01, 1e-5);  // moving away
  // Within the goal radius: terminated, a success, the bonus.
  EXPECT_TRUE(f.task.terminated(0, at(1.85, 0.0, 0)));
  EXPECT_EQ(f.task.outcome(0), Outcome::kSuccess);
  EXPECT_NEAR(f.task.reward(0, at(1.85, 0.0, 0)), 10.0 * 1.85 - 0.01 + 10.0, 1e-4);
  // A wall in front: the collision ends the episode, a failure, the penalty.
  Fixture wall({2.0, 0.0});
  wall.task.reward(0, at(0.5, 0, 0));  // the progress reference
  wall.sense(true);
  EXPECT_TRUE(wall.task.terminated(0, at(0.5, 0, 0)));
  EXPECT_EQ(wall.task.outcome(0), Outcome::kCollision);
  EXPECT_LT(wall.task.reward(0, at(0.5, 0, 0)), -9.0f);
  // Sparse: no progress term.
  Fixture sparse({2.0, 0.0}, config, NavigationTask::Variant::kSparse);
  sparse.task.reward(0, at(0, 0, 0));
  EXPECT_NEAR(sparse.task.reward(0, at(0.5, 0, 0)), -0.01, 1e-6);
}

TEST(NavigationTask, ACloseScanRangeCostsInProportionToItsNearness) {
  NavigationConfig config;  // proximity_distance 0.25 m, proximity_penalty 0.1
  Fixture f({2.0, 0.0}, config, NavigationTask::Variant::kSparse);
  f.task.reward(0, at(0, 0, 0));
  // The fixture's scan holds a too-close return: it reads as range_min (0.1 m).
  EXPECT_NEAR(f.task.reward(0, at(0, 0, 0)), -0.01 - 0.1 * (1.0 - 0.1 / 0.25), 1e-6);
  f.scan = std::vector<float>(8, 0.2f);
  f.sense(false);
  EXPECT_NEAR(f.task.reward(0, at(0, 0, 0)), -0.01 - 0.1 * (1.0 - 0.2 / 0.25), 1e-6);
  f.scan = std::vector<float>(8, 0.3f);  // beyond proximity_distance: no cost
  f.sense(false);
  EXPECT_NEAR(f.task.reward(0, at(0, 0, 0)), -0.01, 1e-6);
}

EnvConfig navConfig(int envs, int threads = 1) {
  EnvConfig c = test::scanningArenaConfig(envs, threads);
  c.episode_length_s = 20.0;
  c.world.num_boxes = 3;
  c.world.num_cylinders = 2;
  return c;
}

TEST(NavigationTask, GoalsAreDrawnInFreeSpaceAwayFromObstacles) {
  EnvConfig c = navConfig(16, 2);
  c.episode_length_s = 0.05;  // many resets
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  int checked = 0;
  for (int s = 0; s < 40; ++s) {
    env.step(std::vector<float>(32, 5.0f));
    for (int e = 0; e < 16; ++e, ++checked) {
      const EnvLayout& l = env.view(e).layout();
      const Eigen::Vector2d g = task.goal(e);
      const double d = (g - l.start).norm();
      EXPECT_GE(d, 1.0 - 1e-9);
      EXPECT_LE(d, 3.0 + 1e-9);
      EXPECT_GE(env.world()->staticClearance(g), 0.3) << "env " << e;
      for (const Obstacle& o : l.obstacles) {
        if (o.placed) {
          EXPECT_GE(o.distance(g), c.world.start_clearance) << "env " << e;
        }
      }
    }
  }
  EXPECT_GT(checked, 600);
}

TEST(NavigationTask, OutcomesOfEndedEpisodesAreReported) {
  EnvConfig c = navConfig(2);
  c.world.num_boxes = 0;
  c.world.num_cylinders = 0;
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  // Env 0 put on its goal: a success at the next step. Env 1 drives on until it hits a wall.
  RootState s = env.view(0).rootState();
  s.position.head<2>() = task.goal(0);
  env.setRootState(0, s);
  bool success = false, failure = false;
  for (int k = 0; k < 1200 && !(success && failure); ++k) {
    const StepResult& r = env.step({0.0f, 0.0f, 20.0f, 20.0f});
    ASSERT_EQ(r.outcomes.size(), r.reset_env_ids.size());
    for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
      if (r.reset_env_ids[i] == 0 && k == 0) {
        EXPECT_EQ(r.outcomes[i], static_cast<std::uint8_t>(Outcome::kSuccess));
        EXPECT_TRUE(r.terminated[0]);
        EXPECT_GT(r.rewards[0], 9.0f);
        success = true;
      }
      if (r.reset_env_ids[i] == 1) {
        EXPECT_EQ(r.outcomes[i], static_cast<std::uint8_t>(Outcome::kCollision));
        EXPECT_LT(r.rewards[1], -9.0f);
        failure = true;
      }
    }
  }
  EXPECT_TRUE(success);
  EXPECT_TRUE(failure);  // 20 rad/s straight on in a 4 x 4 m arena meets a wall within 20 s
}

TEST(NavigationTask, TheSpecCarriesTheBeamsItObservesForARobotElsewhere) {
  EnvConfig c = navConfig(2);
  c.scan.samples = 36;
  c.scan.angles = {-1.75, 1.75};  // 0.1 rad apart
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  t.navigation.beams = 12;  // every third sample
  const BatchSpec spec = BatchedEnv(test::jetbot(), c, makeTask(t)).spec();
  ASSERT_EQ(spec.observer.scan_beam_angles.size(), 12u);
  for (int i = 0; i < 12; ++i)
    EXPECT_NEAR(spec.observer.scan_beam_angles[i], -1.75 + 0.3 * i, 1e-12);
  EXPECT_EQ(spec.observer.scan_range, (std::vector<double>{0.05, 3.5}));
  // A task that observes no scan says so, scanner or not.
  const BatchSpec velocity = BatchedEnv(test::jetbot(), c).spec();
  EXPECT_TRUE(velocity.observer.scan_beam_angles.empty());
  EXPECT_TRUE(velocity.observer.scan_range.empty());
}

TEST(NavigationTask, NeedsAScannerAndNoMoreBeamsThanItHas) {
  EnvConfig c = test::smallConfig(1);
  try {
    BatchedEnv env(test::jetbot(), c, test::navigationTask());
    FAIL() << "accepted without a scanner";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("task = navigation"), std::string::npos) << e.what();
  }
  c.scan.link = "base_link";
  c.scan.samples = 10;
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  try {
    BatchedEnv env(test::jetbot(), c, makeTask(t));
    FAIL() << "accepted 24 beams of 10";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("nav/beams = 24"), std::string::npos) << e.what();
  }
  t.reward_variant = RewardVariant::kExp;
  try {
    makeTask(t);
    FAIL() << "accepted the command task's variant";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("reward_variant = 'exp'"), std::string::npos) << e.what();
  }
}

TEST(ActionSpace, TwistActionsDriveThroughTheDifferentialDrive) {
  EnvConfig c = test::smallConfig(1);
  c.action_space = ActionSpace::kTwist;
  c.episode_length_s = 100.0;
  BatchedEnv env(test::jetbot(), c);
  ASSERT_EQ(env.actionDim(), 2);
  EXPECT_NEAR(env.actionHigh()[0], 20.0 * 0.03, 1e-5);               // v at both wheels' limit
  EXPECT_NEAR(env.actionHigh()[1], 2 * 20.0 * 0.03 / 0.1125, 1e-4);  // omega, wheels opposed
  EXPECT_EQ(env.spec().action_names, (std::vector<std::string>{"linear_x", "angular_z"}));
  for (int k = 0; k < 120; ++k) env.step({0.3f, 0.0f});
  EXPECT_NEAR(env.view(0).rootTwist().linear.x(), 0.3, 0.015);
  EXPECT_NEAR(env.view(0).dofVelocity(0), 10.0, 0.5);
  for (int k = 0; k < 120; ++k) env.step({0.0f, 2.0f});
  EXPECT_NEAR(env.view(0).rootTwist().angular.z(), 2.0, 0.15);
  // Beyond the bounds: clamped, the curvature kept by DiffDrive.
  EXPECT_NO_THROW(env.step({5.0f, 0.0f}));
  EXPECT_THROW(env.step({std::nanf(""), 0.0f}), InputError);
}

TEST(ActionSpace, TwistReverseSpeedBoundsBackwardsTwistsOnly) {
  EnvConfig c = test::smallConfig(1);
  c.action_space = ActionSpace::kTwist;
  c.episode_length_s = 100.0;
  c.twist_reverse_speed = 0.0;  // forwards only
  BatchedEnv env(test::jetbot(), c);
  EXPECT_EQ(env.actionLow()[0], 0.0f);
  EXPECT_NEAR(env.actionHigh()[0], 0.6, 1e-5);  // forwards and turns as before
  EXPECT_NEAR(env.actionLow()[1], -env.actionHigh()[1], 1e-6);
  for (int k = 0; k < 120; ++k) env.step({-0.3f, 0.0f});  // clamped to standing still
  EXPECT_NEAR(env.view(0).rootTwist().linear.x(), 0.0, 1e-3);
  c.twist_reverse_speed = 0.1;
  BatchedEnv slow(test::jetbot(), c);
  EXPECT_FLOAT_EQ(slow.actionLow()[0], -0.1f);
  for (int k = 0; k < 120; ++k) slow.step({-0.3f, 0.0f});
  EXPECT_NEAR(slow.view(0).rootTwist().linear.x(), -0.1, 0.01);
  // Faster than the wheels allow, negative other than -1, or wheel actions: refused naming it.
  const std::vector<std::pair<double, std::string>> bad{
      {0.7, "0.7: must not exceed"}, {-0.5, "-0.5: must be -1"}, {0.2, "0.2: bounds twist"}};
  for (const auto& [value, text] : bad) {
    c.twist_reverse_speed = value;
    c.action_space = value == 0.2 ? ActionSpace::kWheels : ActionSpace::kTwist;
    try {
      BatchedEnv refused(test::jetbot(), c);
      FAIL() << "accepted twist_reverse_speed " << value;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("twist_reverse_speed = " + text), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace jetbot_rl
