// The deploy node reads a robot as the env node's robot view presents one, without a master:
// env 0's odometry and LaserScan messages (filled as the env node fills them) turned into the
// measured state (rootStateOf, resampleScan) and observed by the observer of the env's spec
// (observerOf, from its observation contract) give the simulated task's observation, for every
// task, step after step. One difference is the robot's, not the code's: odometry gives the velocity
// of the base link's origin, the simulated task observes the centre of mass's (lin_vel_b_*), which
// differ by omega x (the COM's offset); those components are compared with the observation of the
// simulated state measured at the link's origin (test_task_observers.cpp proves the simulated
// state's observation exact).
#include <gtest/gtest.h>

#include <random>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/deploy/deploy_driver.h"
#include "jetbot_rl/ros/env_node/robot_state_output.h"
#include "jetbot_rl/ros/env_node/scan_output.h"
#include "jetbot_rl/tasks/command_task.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace {

std::unique_ptr<BatchedEnv> env(TaskKind task) {
  EnvSetup s;
  s.env.num_envs = 2;
  s.env.num_threads = 1;
  s.env.episode_length_s = 2.0;
  s.task.task = task;
  if (task == TaskKind::kNavigation) {
    s.env.action_space = ActionSpace::kTwist;
    s.env.world.arena_size = {4.0, 4.0};
    s.env.world.num_boxes = 2;
    s.env.world.num_cylinders = 1;
    s.env.world.random_start = true;
    s.env.scan.link = "base_link";
    s.env.scan.samples = 72;
    s.env.scan.angles = {-3.14159, 3.05433};
    s.env.scan.range = {0.15, 3.5};
    s.task.navigation.beams = 24;
  }
  return makeEnv(RobotModel::fromUrdfFile(JETBOT_URDF), s);
}

class ObserverAgreement : public ::testing::TestWithParam<TaskKind> {};

TEST_P(ObserverAgreement, TheRobotViewsMessagesObservedAsTheDeployNodeDoGiveTheTasksObservation) {
  const std::unique_ptr<BatchedEnv> batch = env(GetParam());
  const BatchSpec spec = batch->spec();
  const std::unique_ptr<TaskObserver> observer = observerOf(spec, 0.2, "the env's spec");
  const RobotNames names(true);
  nav_msgs::Odometry odom = odometryFrame(*batch, 0, names);
  sensor_msgs::LaserScan scan = scanFrame(*batch, 0, names);
  std::mt19937 gen(7);
  std::vector<float> actions(static_cast<std::size_t>(batch->numEnvs()) * batch->actionDim());
  std::vector<float> obs(static_cast<std::size_t>(batch->obsDim())), ranges;
  int resets = 0;
  for (int step = 0; step < 120; ++step) {
    for (std::size_t i = 0; i < actions.size(); ++i) {
      const std::size_t a = i % batch->actionDim();
      actions[i] =
          std::uniform_real_distribution<float>(batch->actionLow()[a], batch->actionHigh()[a])(gen);
    }
    const StepResult& r = batch->step(actions);
    const bool reset = !r.reset_env_ids.empty() && r.reset_env_ids.front() == 0;
    resets += reset;
    updateOdometry(*batch, 0, ros::Time(step * batch->controlDt()), odom);
    MeasuredState m;
    m.root = rootStateOf(odom);  // the odometry frame is the env's frame
    if (observer->scanBeams() > 0) {
      updateScan(*batch, 0, odom.header.stamp, scan);
      std::string error;
      // the contract's beams: 3 samples a beam, the smallest of each
      ASSERT_TRUE(resampleScan(scan, spec.observer, ranges, error)) << error;
      m.scan = ranges.data();
    }
    if (const auto* nav = dynamic_cast<const NavigationTask*>(&batch->task()))
      m.goal = nav->goal(0);
    if (const auto* cmd = dynamic_cast<const CommandTask*>(&batch->task()))
      m.command = cmd->command(0);
    const std::vector<float> zeros(batch->actionDim(), 0.0f);
    m.last_action = reset ? zeros.data() : actions.data();
    observer->observe(m, obs.data());
    // The simulated state as the robot's odometry measures it: at the base link's origin.
    MeasuredState at_link = m;
    at_link.root = batch->view(0).rootState();
    at_link.root.com_linear_velocity = at_link.root.orientation * batch->view(0).rootTwist().linear;
    std::vector<float> expected(obs.size());
    observer->observe(at_link, expected.data());
    for (int k = 0; k < batch->obsDim(); ++k) {
      const std::string& name = spec.observation_names[k];
      // The odometry's pose and twist equal the state's but for rounding; readings, goal and
      // command are exact.
      ASSERT_NEAR(obs[k], expected[k], 1e-5) << name << " at step " << step;
      if (name.rfind("lin_vel_b_", 0) != 0) {
        ASSERT_NEAR(obs[k], r.observations[k], 1e-5) << name << " at step " << step;
      }
    }
  }
  EXPECT_GT(resets, 0);
}

INSTANTIATE_TEST_SUITE_P(EveryTask, ObserverAgreement,
                         ::testing::Values(TaskKind::kVelocity, TaskKind::kCommand,
                                           TaskKind::kNavigation),
                         [](const ::testing::TestParamInfo<TaskKind>& i) {
                           return enumName(i.param);
                         });

TEST(ObserverOf, ACheckpointWhoseObservationTheTaskDoesNotBuildIsRefusedNamingBoth) {
  BatchSpec trained;
  trained.task = "velocity";
  trained.action_dim = 2;
  trained.observation_names = {"lin_vel_b_x", "lin_vel_b_y"};  // another version's observation
  try {
    observerOf(trained, 0.2, "old.pt");
    FAIL() << "accepted a policy trained on another observation";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("the policy of old.pt was trained on [lin_vel_b_x, "
                                         "lin_vel_b_y]"),
              std::string::npos)
        << e.what();
  }
}

TEST(ObserverOf, APathPolicysObserverComesFromItsContractWithTheGoalToleranceGiven) {
  BatchSpec trained;
  trained.task = "navigation";
  trained.action_dim = 2;
  trained.observer.scan_beam_angles = {0.0};
  trained.observer.scan_range = {0.15, 3.5};
  trained.observer.path_lookahead = 0.6;
  trained.observer.goal_radius = 0.2;
  trained.observation_names = {"beam_0",         "goal_distance", "goal_cos",     "goal_sin",
                               "path_remaining", "path_cos",      "path_sin",     "lin_vel_b_x",
                               "ang_vel_z",      "last_action_0", "last_action_1"};
  const auto observer = observerOf(trained, 0.5, "path.pt");
  EXPECT_EQ(observer->observationNames(), trained.observation_names);
  MeasuredState at;
  at.goal = Eigen::Vector2d(0.4, 0.0);
  EXPECT_TRUE(observer->reached(at));  // within the 0.5 m given, not the 0.2 m trained
  EXPECT_FALSE(observerOf(trained, 0.2, "path.pt")->reached(at));
  // Without the path in its contract, the names are not the policy's: refused.
  trained.observer.path_lookahead = 0.0;
  EXPECT_THROW(observerOf(trained, 0.2, "path.pt"), ConfigError);
}

}  // namespace
}  // namespace jetbot_rl
