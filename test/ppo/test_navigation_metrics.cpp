// The navigation metrics (issue 48) on episodes driven by hand: a robot driving straight at top
// speed to a goal 2 m ahead has SPL and path over the shortest near 1, BARN's top score 0.25 and
// a time near the optimal; one weaving its way there has a lower SPL, a longer path and a yaw rate
// that changes far more; a collision counts in SPL and BARN as 0; the top speed of a twist and
// of wheel targets.
#include <gtest/gtest.h>

#include <cmath>

#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/eval/navigation_metrics.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace {

/// One env on the navigation env's twist, in an empty 8 x 8 m arena, facing +x at the origin,
/// its goal `goal`.
struct StraightRun {
  std::unique_ptr<BatchedEnv> env;
  NavigationTask* task = nullptr;

  explicit StraightRun(const Eigen::Vector2d& goal) {
    EnvSetup setup;
    readEnvSetupFiles({std::string(JETBOT_RL_SOURCE_DIR) + "/config/navigation_env.yaml"}, setup);
    setup.task.task = TaskKind::kNavigation;
    setup.env.num_envs = 1;
    setup.env.num_threads = 1;
    setup.env.randomization.initial_yaw = {0.0, 0.0};
    setup.env.world.random_start = false;
    setup.env.world.arena_size = {8.0, 8.0};
    setup.env.world.families.clear();
    setup.task.navigation.path = false;
    env = makeEnv(
        RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_lidar.urdf"),
        setup);
    task = const_cast<NavigationTask*>(dynamic_cast<const NavigationTask*>(&env->task()));
    if (!task) throw std::runtime_error("not the navigation task");
    task->setGoal(0, goal);
  }

  /// Drives with `action(step)` until the first episode ends; the metrics and its outcome.
  template <typename Action>
  std::pair<NavigationMetricsResult, std::uint8_t> drive(Action action) {
    NavigationMetrics metrics(*env, *task, topSpeed(env->spec()));
    for (int step = 0; step < 1000; ++step) {
      metrics.beforeStep(*env);
      const std::uint32_t length = env->state().episode_steps[0];
      const StepResult r = env->step(action(step));
      if (!r.reset_env_ids.empty()) {
        metrics.episodeEnded(0, r.outcomes[0], length + 1);
        metrics.afterStep(*env, r);
        return {metrics.result(), r.outcomes[0]};
      }
      metrics.afterStep(*env, r);
    }
    ADD_FAILURE() << "no episode ended";
    return {};
  }
};

constexpr auto kSuccess = static_cast<std::uint8_t>(Outcome::kSuccess);

TEST(NavigationMetrics, AStraightDriveAtTopSpeedScoresNearTheBestAndAWeavingOneWorse) {
  StraightRun straight({2.0, 0.0});
  const double top = topSpeed(straight.env->spec());
  EXPECT_NEAR(top, 0.6, 1e-6);  // the twist's linear_x bound (a float)
  const auto [m, outcome] = straight.drive([](int) { return std::vector<float>{0.6f, 0.0f}; });
  ASSERT_EQ(outcome, kSuccess);
  EXPECT_NEAR(m.path_ratio, 1.0, 0.03);
  EXPECT_NEAR(m.spl, 1.0, 0.03);
  EXPECT_DOUBLE_EQ(m.barn_score, 0.25);  // within 4 x the optimal time: BARN's best
  EXPECT_GT(m.time_ratio, 1.0);          // it starts from rest
  EXPECT_LT(m.time_ratio, 1.3);
  EXPECT_NEAR(m.time_to_goal, m.time_ratio * 1.8 / top, 1e-9);  // 2 m less the goal's 0.2 m
  EXPECT_LT(m.angular_smoothness, 0.5);

  StraightRun weaving({2.0, 0.0});
  // Steering for the goal with a heading 0.4 sin(2 pi t / 1 s) rad off its line (control steps of
  // 0.05 s): it gets there, swinging left and right.
  const BatchedEnv& batch = *weaving.env;
  const auto [w, weave_outcome] = weaving.drive([&batch](int step) {
    const RootState s = batch.view(0).rootState();
    const Eigen::Vector2d to_goal = Eigen::Vector2d(2.0, 0.0) - s.position.head<2>();
    const Eigen::Vector3d forward = s.orientation * Eigen::Vector3d::UnitX();
    const double yaw = std::atan2(forward.y(), forward.x());
    const double wanted =
        std::atan2(to_goal.y(), to_goal.x()) + 0.4 * std::sin(2 * kPi * step * 0.05);
    return std::vector<float>{0.5f,
                              static_cast<float>(4.0 * std::remainder(wanted - yaw, 2 * kPi))};
  });
  ASSERT_EQ(weave_outcome, kSuccess);
  EXPECT_GT(w.path_ratio, m.path_ratio);
  EXPECT_LT(w.spl, m.spl);
  EXPECT_GT(w.time_ratio, m.time_ratio);
  EXPECT_GT(w.angular_smoothness, 10.0 * std::max(m.angular_smoothness, 0.1));
}

TEST(NavigationMetrics, ACollisionScoresZeroInSplAndBarn) {
  // A goal behind the arena's wall's side: driving straight at it ends on the wall at x = 4 m.
  StraightRun run({3.5, 0.0});
  run.task->setGoal(0, {3.5, 3.5});
  const auto [m, outcome] = run.drive([](int) { return std::vector<float>{0.6f, 0.0f}; });
  ASSERT_NE(outcome, kSuccess);
  EXPECT_EQ(m.spl, 0.0);
  EXPECT_EQ(m.barn_score, 0.0);
  EXPECT_EQ(m.time_to_goal, 0.0);  // no success to average
}

TEST(NavigationMetrics, TheTopSpeedOfWheelTargetsIsTheSlowestWheelsBoundTimesTheRadius) {
  BatchSpec spec;
  spec.action_names = {"left_wheel_joint", "right_wheel_joint"};
  spec.action_high = {20.0, 18.0};
  spec.observer.wheel_radius = 0.03;
  EXPECT_NEAR(topSpeed(spec), 18.0 * 0.03, 1e-12);
  spec.observer.wheel_radius = 0.0;  // no kinematics known: no top speed
  EXPECT_EQ(topSpeed(spec), 0.0);
  spec.action_names = twistActionNames();
  spec.action_high = {0.26, 1.8};
  EXPECT_NEAR(topSpeed(spec), 0.26, 1e-6);
}

}  // namespace
}  // namespace jetbot_rl
