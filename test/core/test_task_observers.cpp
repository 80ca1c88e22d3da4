// The task observers: for every task, the observer a robot elsewhere builds from the env's spec
// (makeObserver) computes from the env's measured state (root state, the scan at the observed
// beams, goal or command, last action) exactly the observation the simulated task gave, bit for
// bit, step after step (beams on a log scale too); and the navigation observer's goal test is the
// task's success test.
#include <cmath>
#include <random>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/scan_reading.h"
#include "jetbot_rl/tasks/command_task.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/tasks/task_factory.h"
#include "navigation_fixture.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

EnvConfig config(TaskKind task) {
  EnvConfig c = test::smallConfig(3, 2);
  c.episode_length_s = 2.0;  // episodes end within the run
  if (task == TaskKind::kNavigation) {
    c.action_space = ActionSpace::kTwist;
    c.world.arena_size = {4.0, 4.0};
    c.world.num_boxes = 2;
    c.world.num_cylinders = 2;
    c.world.random_start = true;
    c.scan.link = "base_link";
    c.scan.samples = 36;
    c.scan.range = {0.15, 3.5};
    c.scan.noise_std = 0.01;
  }
  return c;
}

/// Env `e`'s scan read at the spec's beams (angles and sectors), as a robot's scan is read.
std::vector<float> scanAtBeams(const BatchedEnv& env, int e, const BatchSpec& spec) {
  const ScannerSpec& s = *env.scanner();
  const ScanView view{env.view(e).scan(), s.samples, s.min_angle, s.angleIncrement()};
  std::vector<float> ranges(spec.observer.scan_beam_angles.size());
  std::string error;
  EXPECT_TRUE(readBeams(view, spec.observer.scan_beam_angles, spec.observer.scan_beam_width,
                        ranges.data(), error))
      << error;
  return ranges;
}

/// Steps an env of task `t` with random actions and checks the spec's observer against it.
void expectTheSpecsObserverAgrees(const TaskConfig& t) {
  BatchedEnv env(test::jetbot(), config(t.task), makeTask(t));
  const BatchSpec spec = env.spec();
  const std::unique_ptr<TaskObserver> observer = makeObserver(spec);  // as a robot builds it
  ASSERT_EQ(observer->observationNames(), spec.observation_names);
  std::mt19937 gen(3);
  std::vector<float> actions(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
  std::vector<float> obs(static_cast<std::size_t>(env.obsDim()));
  int compared = 0, ended = 0;
  for (int step = 0; step < 150; ++step) {
    for (std::size_t i = 0; i < actions.size(); ++i) {
      const std::size_t a = i % env.actionDim();
      std::uniform_real_distribution<float> in(env.actionLow()[a], env.actionHigh()[a]);
      actions[i] = in(gen);  // within the bounds: the last action the policy took
    }
    const StepResult& r = env.step(actions);
    ended += static_cast<int>(r.reset_env_ids.size());
    for (int e = 0; e < env.numEnvs(); ++e) {
      const bool reset = std::find(r.reset_env_ids.begin(), r.reset_env_ids.end(),
                                   static_cast<std::uint32_t>(e)) != r.reset_env_ids.end();
      MeasuredState m;
      m.root = env.view(e).rootState();
      std::vector<float> beams;
      if (observer->scanBeams() > 0) {
        beams = scanAtBeams(env, e, spec);
        m.scan = beams.data();
      }
      if (const auto* nav = dynamic_cast<const NavigationTask*>(&env.task())) m.goal = nav->goal(e);
      if (const auto* cmd = dynamic_cast<const CommandTask*>(&env.task())) {
        m.command = cmd->command(e);
      }
      const std::vector<float> zeros(env.actionDim(), 0.0f);
      m.last_action =
          reset ? zeros.data() : &actions[static_cast<std::size_t>(e) * env.actionDim()];
      observer->observe(m, obs.data());
      for (int k = 0; k < env.obsDim(); ++k) {
        ASSERT_EQ(obs[k], r.observations[static_cast<std::size_t>(e) * env.obsDim() + k])
            << spec.observation_names[k] << " of env " << e << " at step " << step;
      }
      // An env that goes on has not reached its goal.
      if (!reset) {
        EXPECT_FALSE(observer->reached(m)) << "env " << e << " at step " << step;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 150 * env.numEnvs());
  EXPECT_GT(ended, 0);  // resets happened: first observations compared too
}

class TaskObservers : public ::testing::TestWithParam<TaskKind> {};

TEST_P(TaskObservers, TheObserverOfTheSpecObservesWhatTheSimulatedTaskObserved) {
  TaskConfig t;
  t.task = GetParam();
  expectTheSpecsObserverAgrees(t);
}

TEST(NavigationObserver, BeamsOnALogScaleAreObservedOnARobotAsInTheTask) {
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  t.navigation.log_beams = true;
  expectTheSpecsObserverAgrees(t);
}

TEST(NavigationObserver, BeamsOnALogScaleTellNearRangesApart) {
  const NavigationObserver linear(2, 0.15, 3.5, 2, 0.2);
  const NavigationObserver log(2, 0.15, 3.5, 2, 0.2, false, true);
  EXPECT_EQ(log.observationNames().front(), "beam_log_0");
  EXPECT_FLOAT_EQ(log.beamValue(0.15f), 0.0f);
  EXPECT_FLOAT_EQ(log.beamValue(3.5f), 1.0f);
  EXPECT_FLOAT_EQ(log.beamValue(-INFINITY), 0.0f);  // too close: range_min
  EXPECT_FLOAT_EQ(log.beamValue(INFINITY), 1.0f);   // no return: range_max
  EXPECT_FLOAT_EQ(log.beamValue(NAN), 1.0f);
  EXPECT_FLOAT_EQ(log.beamValue(0.01f), 0.0f);  // clamped into the range
  EXPECT_FLOAT_EQ(log.beamValue(50.0f), 1.0f);
  // log(r / 0.15) / log(3.5 / 0.15): 0.2 m lies 0.0912 above 0.15 m (on a linear scale 0.0143)
  EXPECT_NEAR(log.beamValue(0.2f) - log.beamValue(0.15f),
              std::log(0.2 / 0.15) / std::log(3.5 / 0.15), 1e-6);
  EXPECT_GT(log.beamValue(0.2f) - log.beamValue(0.15f),
            5.0f * (linear.beamValue(0.2f) - linear.beamValue(0.15f)));
  std::vector<float> low(log.observationNames().size()), high(low.size());
  log.observationBounds(low, high);
  EXPECT_EQ(low[0], 0.0f);
  EXPECT_EQ(high[0], 1.0f);
  // A scanner whose range starts at 0 has no log scale: refused naming the parameter.
  try {
    NavigationObserver(2, 0.0, 3.5, 2, 0.2, false, true);
    FAIL() << "accepted range_min 0";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("nav/log_beams"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTask, TaskObservers,
                         ::testing::Values(TaskKind::kVelocity, TaskKind::kCommand,
                                           TaskKind::kNavigation),
                         [](const ::testing::TestParamInfo<TaskKind>& i) {
                           return enumName(i.param);
                         });

TEST(NavigationObserver, ItsGoalTestIsTheTasksSuccess) {
  NavigationConfig c;
  c.goal_radius = 0.3;
  const Eigen::Vector2d goal(1.0, -0.5);
  test::NavigationFixture f(goal, c);
  ObserverSpec o;
  o.scan_beam_angles = {-1.0, 0.0, 1.0, 2.0};
  o.scan_range = {0.1, 4.0};
  o.goal_radius = 0.3;
  const std::unique_ptr<TaskObserver> observer = makeObserver("navigation", 2, o);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> offset(-0.5, 0.5);
  int inside = 0;
  for (int k = 0; k < 2000; ++k) {
    RootState s;
    s.position = Eigen::Vector3d(goal.x() + offset(gen), goal.y() + offset(gen), 0.03);
    MeasuredState m;
    m.root = s;
    m.goal = goal;
    const bool success = f.task.terminated(0, s) && f.task.outcome(0) == Outcome::kSuccess;
    ASSERT_EQ(observer->reached(m), success) << "at " << s.position.transpose();
    inside += success;
  }
  EXPECT_GT(inside, 100);  // both answers were tried
  EXPECT_LT(inside, 1900);
}

TEST(ObservationContract, TheSpecHoldsWhatTheTaskObservesWithAndTheRobotsGeometry) {
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  t.navigation.log_beams = true;
  t.navigation.path = true;
  t.navigation.path_lookahead = 0.7;
  t.navigation.path_clearance = 0.25;
  t.navigation.path_clearance_cost = 3.0;
  t.navigation.goal_radius = 0.15;
  BatchedEnv env(test::jetbot(), config(t.task), makeTask(t));
  const BatchSpec spec = env.spec();
  const ObserverSpec& o = spec.observer;
  EXPECT_TRUE(o.log_beams);
  EXPECT_EQ(o.path_lookahead, 0.7);
  EXPECT_EQ(o.path_clearance, 0.25);
  EXPECT_EQ(o.path_clearance_cost, 3.0);
  EXPECT_EQ(o.goal_radius, 0.15);
  EXPECT_EQ(o.scan_range, (std::vector<double>{0.15, 3.5}));
  EXPECT_EQ(o.footprint_radius, env.robot().footprintRadius());
  EXPECT_GT(o.wheel_radius, 0.0);
  EXPECT_GT(o.wheel_separation, o.wheel_radius);
  // Built from the contract alone: the names the task observes, path and log scale included.
  EXPECT_EQ(makeObserver(spec)->observationNames(), spec.observation_names);
  EXPECT_EQ(spec.observation_names.front(), "beam_log_0");
  // The contract sets a benchmark's or a tool's task as the policy was trained.
  NavigationConfig again;
  takeObservationContract(o, again);
  EXPECT_EQ(fieldsToYaml(again), fieldsToYaml(t.navigation));
  // Without a path, the path's settings are none of the contract.
  t.navigation.path = false;
  const BatchSpec no_path = BatchedEnv(test::jetbot(), config(t.task), makeTask(t)).spec();
  EXPECT_EQ(no_path.observer.path_lookahead, 0.0);
  EXPECT_EQ(no_path.observer.path_clearance, 0.0);
}

TEST(MakeObserver, RefusesAnUnknownTaskAndANavigationObserverWithoutBeams) {
  ObserverSpec o;
  EXPECT_THROW(makeObserver("dance", 2, o), ConfigError);
  try {
    makeObserver("navigation", 2, o);
    FAIL() << "built a navigation observer without beams";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("0 scan beams"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace jetbot_rl
