// Several robots in one world (robots_per_env): the batch has num_envs x K rows, the robots of
// an env start on its circle and see and hit each other, the same on any thread count; bad
// parameters are refused naming the field.
#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// `num_envs` 4 x 4 m arenas, `k` scanning robots each, on a circle of `radius` (0: random
/// starts).
EnvConfig teamConfig(int num_envs, int k, double radius, int threads = 1) {
  EnvConfig c = test::scanningArenaConfig(num_envs, threads);
  c.team.robots_per_env = k;
  c.team.swap_radius = radius;
  return c;
}

double yawOf(const RootState& s) {
  const Eigen::Vector3d forward = s.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

TEST(Team, TheBatchHasARowPerRobotAndTheRobotsOfAnEnvStartOnItsCircle) {
  const int n = 3, k = 5;
  const double radius = 1.2;
  BatchedEnv env(test::lidarJetbot(), teamConfig(n, k, radius), test::navigationTask());
  ASSERT_EQ(env.numEnvs(), n * k);
  EXPECT_EQ(env.spec().num_envs, n * k);
  EXPECT_EQ(env.state().observations.size(), static_cast<std::size_t>(n * k * env.obsDim()));
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  for (int e = 0; e < n; ++e) {
    for (int r = 0; r < k; ++r) {
      const int row = e * k + r;
      // The robots of an env share its origin; envs keep theirs apart.
      EXPECT_TRUE(env.view(row).origin().isApprox(env.view(e * k).origin())) << "row " << row;
      if (e > 0) {
        EXPECT_FALSE(env.view(row).origin().isApprox(env.view(0).origin()));
      }
      const RootState s = env.view(row).rootState();
      const double a = 2.0 * kPi * r / k;
      const Eigen::Vector2d own(radius * std::cos(a), radius * std::sin(a));
      EXPECT_LT((s.position.head<2>() - own).norm(), 1e-6) << "row " << row;
      EXPECT_LT((task.goal(row) + own).norm(), 1e-9) << "row " << row << ": the opposite point";
      // Facing the centre (initial_yaw 0).
      EXPECT_NEAR(std::remainder(yawOf(s) - (a + kPi), 2.0 * kPi), 0.0, 1e-6) << "row " << row;
    }
  }
}

TEST(Team, RobotsSeeEachOtherInTheirScans) {
  // On base_link (below the chassis top) and on the URDF's own scanner, whose rays pass above
  // the chassis: the other's lidar housing stands in their plane.
  for (const std::string link : {"base_link", ""}) {
    SCOPED_TRACE("scan/link '" + link + "'");
    EnvConfig c = teamConfig(1, 2, 0.0);
    c.scan.link = link;
    c.scan.angles = {-kPi, kPi - 2.0 * kPi / c.scan.samples};  // a beam straight ahead
    c.scan.noise_std = 0.0;
    c.scan.update_every = 1;  // the Gazebo block's 5.5 Hz would skip steps
    BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
    const std::vector<float> stop(2 * env.actionDim(), 0.0f);
    const ScannerSpec& scanner = *env.scanner();
    const int ahead = static_cast<int>(std::lround(-scanner.min_angle / scanner.angleIncrement()));
    ASSERT_NEAR(scanner.min_angle + ahead * scanner.angleIncrement(), 0.0, 1e-6);
    const auto front = [&](int row) { return env.view(row).scan()[ahead]; };
    test::place(env, 0, Eigen::Vector2d(-1.0, 0.0), 0.0);
    test::place(env, 1, Eigen::Vector2d(0.0, 0.0), kPi);
    env.step(stop);
    // Robot 1 stands 1 m ahead of robot 0 (its footprint about 0.1 m), the wall 3 m ahead.
    const double gap = 1.0 - env.robot().footprintRadius();
    EXPECT_NEAR(front(0), gap, 0.1);
    EXPECT_NEAR(front(1), gap, 0.1);
    test::place(env, 1, Eigen::Vector2d(-1.0, 1.5), kPi);  // out of the way
    env.step(stop);
    EXPECT_GT(front(0), 2.5);
  }
}

TEST(Team, TwoRobotsDrivingIntoEachOtherEndAsARobotCollision) {
  BatchedEnv env(test::lidarJetbot(), teamConfig(1, 2, 0.0), test::navigationTask());
  auto& task = dynamic_cast<NavigationTask&>(env.task());
  test::place(env, 0, Eigen::Vector2d(-0.6, 0.0), 0.0);
  test::place(env, 1, Eigen::Vector2d(0.6, 0.0), kPi);
  task.setGoal(0, Eigen::Vector2d(-0.6, 1.5));  // neither is reached on the way
  task.setGoal(1, Eigen::Vector2d(0.6, -1.5));
  std::vector<float> ahead(2 * env.actionDim(), 0.0f);
  for (std::size_t i = 0; i < ahead.size(); ++i) ahead[i] = env.actionHigh()[i % env.actionDim()];
  std::vector<int> outcome(2, -1);
  for (int step = 0; step < 100 && (outcome[0] < 0 || outcome[1] < 0); ++step) {
    const StepResult& r = env.step(ahead);
    for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
      if (outcome[r.reset_env_ids[i]] < 0) outcome[r.reset_env_ids[i]] = r.outcomes[i];
    }
  }
  EXPECT_EQ(outcome[0], static_cast<int>(Outcome::kCollisionRobot));
  EXPECT_EQ(outcome[1], static_cast<int>(Outcome::kCollisionRobot));
}

// A robot that drove away leaves no stand-in behind in the other's world: the step after it was
// last near, its stand-in is parked (the steps after that skip the stand-ins altogether).
TEST(Team, ARobotThatDroveAwayLeavesNoStandInWhereItWas) {
  BatchedEnv env(test::lidarJetbot(), teamConfig(1, 2, 0.0), test::navigationTask());
  auto& task = dynamic_cast<NavigationTask&>(env.task());
  test::place(env, 0, Eigen::Vector2d(-0.5, 0.0), 0.0);
  test::place(env, 1, Eigen::Vector2d(-0.1, 0.0), 0.0);  // 0.4 m ahead of robot 0: near it
  task.setGoal(0, Eigen::Vector2d(1.5, 1.5));            // neither is reached on the way
  task.setGoal(1, Eigen::Vector2d(1.5, -1.5));
  const int dim = env.actionDim();
  std::vector<float> actions(2 * dim, 0.0f);
  const auto drive = [&](int row, bool on) {
    for (int i = 0; i < dim; ++i) actions[row * dim + i] = on ? env.actionHigh()[i] : 0.0f;
  };
  const auto x = [&](int row) { return env.view(row).rootState().position.x(); };
  int ended = 0;
  // Robot 1 drives 0.5 m ahead and stops; robot 0 stands.
  drive(1, true);
  for (int step = 0; step < 200 && x(1) < 0.4; ++step) {
    ended += static_cast<int>(env.step(actions).reset_env_ids.size());
  }
  ASSERT_GE(x(1), 0.4);
  drive(1, false);
  // Robot 0 drives through where robot 1 was when it was last near (about x = 0), up to 0.55 m
  // short of robot 1: a stand-in left there would end its episode as a robot collision.
  drive(0, true);
  for (int step = 0; step < 200 && x(0) < x(1) - 0.55; ++step) {
    ended += static_cast<int>(env.step(actions).reset_env_ids.size());
  }
  EXPECT_EQ(ended, 0) << "an episode ended on the way";
  EXPECT_GE(x(0), x(1) - 0.55) << "robot 0 stopped at x = " << x(0);
}

TEST(Team, ARobotStartsAnewClearOfTheOthersAndAloneWhenItsRowIsReset) {
  BatchedEnv env(test::lidarJetbot(), teamConfig(2, 3, 1.0), test::navigationTask());
  // Robot 1 of env 0 parked on robot 0's point: robot 0, reset, takes another point.
  test::place(env, 1, Eigen::Vector2d(1.0, 0.0), 0.0);
  const RootState other_env = env.view(4).rootState();
  const RootState robot2 = env.view(2).rootState();
  env.reset({0});
  const Eigen::Vector2d p = env.view(0).rootState().position.head<2>();
  EXPECT_NEAR(p.norm(), 1.0, 1e-6) << "on the circle";
  EXPECT_GE((p - Eigen::Vector2d(1.0, 0.0)).norm(), 0.4) << "clear of robot 1";
  EXPECT_GE((p - robot2.position.head<2>()).norm(), 0.4) << "clear of robot 2";
  EXPECT_TRUE(env.view(4).rootState().position.isApprox(other_env.position));
  EXPECT_TRUE(env.view(2).rootState().position.isApprox(robot2.position));
}

TEST(Team, TheSameOnAnyThreadCountAndAfterAReseed) {
  const auto run = [](int threads, bool rounds) {
    EnvConfig c = teamConfig(4, 5, 1.2, threads);
    c.team.rounds = rounds;
    c.randomization.initial_yaw = {-0.5, 0.5};  // a draw at every reset
    BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
    Rng rng(3);
    std::vector<float> out, actions(env.numEnvs() * env.actionDim());
    int waits = 0;
    for (int pass = 0; pass < 2; ++pass) {
      env.reset({}, 11);
      for (int step = 0; step < 400; ++step) {
        for (std::size_t i = 0; i < actions.size(); ++i) {
          actions[i] = static_cast<float>(env.actionHigh()[i % env.actionDim()] * rng.uniform());
        }
        const StepResult& r = env.step(actions);
        out.insert(out.end(), r.observations.begin(), r.observations.end());
        for (std::uint8_t o : r.outcomes) {
          out.push_back(o);
          waits += o == static_cast<std::uint8_t>(Outcome::kWaited);
        }
      }
    }
    EXPECT_EQ(waits > 0, rounds) << "rounds " << rounds << ": waits ended " << waits;
    return out;
  };
  for (bool rounds : {false, true}) {
    const std::vector<float> one = run(1, rounds), two = run(2, rounds);
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(std::equal(one.begin(), one.end(), two.begin()))
        << "1 and 2 threads differ, rounds " << rounds;
  }
}

/// The index of the scan sample of `row` nearest the bearing of point `p` [m].
int sampleTowards(const BatchedEnv& env, int row, const Eigen::Vector2d& p) {
  const RootState s = env.view(row).rootState();
  const Eigen::Vector2d d = p - s.position.head<2>();
  const double bearing = std::remainder(std::atan2(d.y(), d.x()) - yawOf(s), 2.0 * kPi);
  const ScannerSpec& scanner = *env.scanner();
  return static_cast<int>(std::lround((bearing - scanner.min_angle) / scanner.angleIncrement()));
}

TEST(Team, InRoundsARobotThatEndedWaitsUnseenUntilAllHaveEnded) {
  EnvConfig c = teamConfig(1, 3, 1.0);
  c.team.rounds = true;
  BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
  auto& task = dynamic_cast<NavigationTask&>(env.task());
  const std::vector<float> stop(3 * env.actionDim(), 0.0f);
  const int dim = env.obsDim();
  const auto at = [&](int row) {
    return Eigen::Vector2d(env.view(row).rootState().position.head<2>());
  };
  const Eigen::Vector2d start0 = at(0), start1 = at(1), start2 = at(2);
  const int towards0 = sampleTowards(env, 1, start0);
  const double gap = (start0 - start1).norm() - env.robot().footprintRadius();
  env.step(stop);
  EXPECT_NEAR(env.view(1).scan()[towards0], gap, 0.1) << "robot 1 sees robot 0";

  // Robot 0, driving, reaches its goal: its episode ends, and it waits where it stopped.
  std::vector<float> drive = stop;
  for (int i = 0; i < env.actionDim(); ++i) drive[i] = env.actionHigh()[i];
  for (int step = 0; step < 3; ++step) env.step(drive);
  ASSERT_GT(env.view(0).rootState().com_linear_velocity.norm(), 0.05);
  const Eigen::Vector2d goal0 = at(0);
  task.setGoal(0, goal0);
  const StepResult& r = env.step(drive);
  ASSERT_EQ(r.reset_env_ids, std::vector<std::uint32_t>{0});
  EXPECT_EQ(r.outcomes[0], static_cast<std::uint8_t>(Outcome::kSuccess));
  const std::vector<float> kept(r.observations.begin(), r.observations.begin() + dim);
  EXPECT_TRUE(std::equal(kept.begin(), kept.end(), r.final_observations.begin()));
  const std::uint32_t steps0 = r.episode_steps[0];
  const Eigen::Vector2d stopped0 = at(0);
  EXPECT_EQ(env.view(0).rootState().com_linear_velocity.norm(), 0.0);
  EXPECT_EQ(env.view(0).rootTwist().linear.norm(), 0.0);
  for (int step = 0; step < 5; ++step) {  // told to drive on, it does not
    const StepResult& w = env.step(drive);
    EXPECT_TRUE(w.reset_env_ids.empty());
    EXPECT_EQ(w.rewards[0], 0.0f);
    EXPECT_FALSE(w.terminated[0] || w.truncated[0]);
    EXPECT_EQ(w.episode_steps[0], steps0);
    EXPECT_TRUE(std::equal(kept.begin(), kept.end(), w.observations.begin()));
  }
  EXPECT_EQ(at(0), stopped0) << "it stands still";
  EXPECT_GT(env.view(1).scan()[towards0], gap + 0.5) << "robot 1 no longer sees robot 0";

  // Robot 1 ends; robot 2 still drives on, so the round goes on.
  task.setGoal(1, at(1));
  ASSERT_EQ(env.step(stop).reset_env_ids, std::vector<std::uint32_t>{1});
  // Robot 2 ends last: the round is over, the waiting rows end their waits, all start anew.
  task.setGoal(2, at(2));
  const std::vector<float> waited1(env.state().observations.begin() + dim,
                                   env.state().observations.begin() + 2 * dim);
  const StepResult& end = env.step(stop);
  ASSERT_EQ(end.reset_env_ids, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(end.outcomes, (std::vector<std::uint8_t>{5, 5, 1}));
  EXPECT_TRUE(end.truncated[0] && end.truncated[1] && !end.truncated[2]);
  EXPECT_TRUE(std::equal(waited1.begin(), waited1.end(), end.final_observations.begin() + dim));
  EXPECT_LT((at(0) - start0).norm(), 1e-6);
  EXPECT_LT((at(1) - start1).norm(), 1e-6);
  EXPECT_LT((at(2) - start2).norm(), 1e-6);
  for (int row = 0; row < 3; ++row) EXPECT_EQ(end.episode_steps[row], 0u) << "row " << row;
  EXPECT_NEAR(env.view(1).scan()[towards0], gap, 0.1) << "robot 1 sees robot 0 again";
}

TEST(Team, BadParametersAreRefusedNamingTheField) {
  EnvConfig c = teamConfig(1, 3, 1.0);
  c.world.num_boxes =
      2;  // on a circle swap's points (random starts share them: test_team_obstacles)
  test::expectRefused(test::lidarJetbot(), c, "swap_radius");
  c = teamConfig(1, 3, 1.0);
  c.world.families = {"clutter"};  // walls on the circle's points (random starts share
  c.world.num_boxes = 0;           // layouts: test_team_obstacles)
  test::expectRefused(test::lidarJetbot(), c, "swap_radius");
  c = teamConfig(1, 3, 0.0);
  c.world.random_start = false;
  test::expectRefused(test::lidarJetbot(), c, "robots_per_env");
  c = teamConfig(1, 3, 1.0);
  c.world.arena_size.clear();
  test::expectRefused(test::lidarJetbot(), c, "robots_per_env");
  test::expectRefused(test::lidarJetbot(), teamConfig(1, 30, 1.0),
                      "robots_per_env");  // 0.21 m apart: they do not fit
  test::expectRefused(test::lidarJetbot(), teamConfig(1, 3, 1.9),
                      "swap_radius");  // the points touch the walls
  c = teamConfig(1, 3, 0.0);
  c.team.robots_per_env = 0;
  test::expectRefused(test::lidarJetbot(), c, "robots_per_env");
  c = teamConfig(1, 1, 1.0);
  c.team.rounds = true;  // rounds of one robot
  test::expectRefused(test::lidarJetbot(), c, "rounds");
}

}  // namespace
}  // namespace jetbot_rl
