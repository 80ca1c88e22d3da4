// People and several robots in one world (robots_per_env with movers/num_people): each robot
// sees both and hits both, the people of a world are the same for all its robots, and the batch
// is the same on any thread count.
#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/scene/movers.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

constexpr int kRobots = 4, kPeople = 5;

/// `num_envs` 6 x 6 m arenas, each with kRobots scanning robots at random starts and kPeople
/// people walking by the social force.
EnvConfig crowdConfig(int num_envs, int threads, bool rounds = false) {
  EnvConfig c = test::scanningArenaConfig(num_envs, threads);
  c.world.arena_size = {6.0, 6.0};
  c.scan.samples = 90;
  c.team.robots_per_env = kRobots;
  c.team.rounds = rounds;
  c.movers.num_people = kPeople;
  c.movers.start_clearance = 0.5;
  return c;
}

/// The scan of row `row` cast anew from its physics pose against its world and `moving`.
std::vector<float> castAt(const BatchedEnv& env, int row, const std::vector<Obstacle>* moving) {
  const EnvView view = env.view(row);
  const ScannerSpec& spec = *env.scanner();
  Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
  for (const LinkPose& p : view.linkPoses()) {
    if (p.link == env.robot().bodies()[spec.body].link_name) sensor = p.pose * spec.pose_in_body;
  }
  sensor.translation() -= view.origin();
  Rng noise;
  std::vector<float> ranges(spec.samples);
  castScan(spec, env.world(), view.layout().obstacles, sensor, noise, ranges.data(), moving);
  return ranges;
}

TEST(TeamWithPeople, RobotsAndPeopleShareAWorldAndAreBothSeen) {
  BatchedEnv env(test::lidarJetbot(), crowdConfig(4, 2), test::navigationTask());
  ASSERT_EQ(env.numEnvs(), 4 * kRobots);
  // Every robot of a world meets the same people, drawn clear of all the robots' starts.
  for (int row = 0; row < env.numEnvs(); ++row) {
    const std::vector<Obstacle>& people = env.view(row).movers();
    ASSERT_EQ(people.size(), static_cast<std::size_t>(kPeople));
    const std::vector<Obstacle>& first = env.view(row - row % kRobots).movers();
    EXPECT_EQ(&people, &first) << "row " << row;
    const Eigen::Vector2d start = env.view(row).layout().start;
    for (const Obstacle& p : people) {
      ASSERT_TRUE(p.placed);
      EXPECT_GE((p.center - start).norm(), 0.5 + p.radius - 1e-9) << "row " << row;
    }
  }
  Rng rng(5);
  std::vector<float> actions(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
  int robots_seen = 0, people_seen = 0;
  for (int step = 0; step < 300; ++step) {
    // Mostly forwards, turning at random: the robots roam the arena.
    for (std::size_t i = 0; i < actions.size(); ++i) {
      const double high = env.actionHigh()[i % env.actionDim()];
      actions[i] = static_cast<float>(high * (1.5 * rng.uniform() - 0.5));
    }
    const StepResult& r = env.step(actions);
    for (float o : r.observations) ASSERT_TRUE(std::isfinite(o)) << "step " << step;
    for (int row = 0; row < env.numEnvs(); ++row) {
      if (!env.view(row).scanned()) continue;
      // Beams shorter than the world and the people: another robot; shorter than the world
      // and as long as the world and the people: a person.
      const float* scan = env.view(row).scan();
      const std::vector<float> bare = castAt(env, row, nullptr);
      const std::vector<float> people = castAt(env, row, &env.view(row).movers());
      for (std::size_t k = 0; k < bare.size(); ++k) {
        ASSERT_LE(scan[k], people[k]) << "row " << row << " beam " << k;
        if (scan[k] < people[k]) ++robots_seen;
        if (scan[k] == people[k] && people[k] < bare[k]) ++people_seen;
      }
    }
  }
  EXPECT_GT(robots_seen, 100);
  EXPECT_GT(people_seen, 100);
}

TEST(TeamWithPeople, ARobotHitsAnotherRobotAndAPersonOfItsWorld) {
  EnvConfig c = crowdConfig(2, 1);
  c.movers.avoid_robot = false;  // the people walk on into a robot in their way
  BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
  // Robots 0 and 1 of world 0 face each other 0.6 m apart; robot 0 of world 1 stands 0.5 m
  // ahead of person 0 of its world, facing it.
  test::place(env, 0, Eigen::Vector2d(-0.3, 0.0), 0.0);
  test::place(env, 1, Eigen::Vector2d(0.3, 0.0), kPi);
  const Obstacle person = env.view(kRobots).movers()[0];
  ASSERT_TRUE(person.placed);
  Eigen::Vector2d way = env.movers()->waypoint(1, 0) - person.center;
  ASSERT_GT(way.norm(), 1e-6);
  way.normalize();
  test::place(env, kRobots, person.center + 0.5 * way, std::atan2(-way.y(), -way.x()));
  std::vector<float> ahead(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
  for (std::size_t i = 0; i < ahead.size(); ++i) ahead[i] = env.actionHigh()[i % env.actionDim()];
  std::vector<int> outcome(env.numEnvs(), -1);
  for (int step = 0; step < 60; ++step) {
    const StepResult& r = env.step(ahead);
    for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
      if (outcome[r.reset_env_ids[i]] < 0) outcome[r.reset_env_ids[i]] = r.outcomes[i];
    }
  }
  const int robot = static_cast<int>(Outcome::kCollisionRobot);
  EXPECT_EQ(outcome[0], robot);
  EXPECT_EQ(outcome[1], robot);
  EXPECT_EQ(outcome[kRobots], static_cast<int>(Outcome::kCollisionMover));
}

TEST(TeamWithPeople, TheSameOnAnyThreadCount) {
  const auto run = [](int threads, bool rounds) {
    BatchedEnv env(test::lidarJetbot(), crowdConfig(3, threads, rounds), test::navigationTask());
    Rng rng(3);
    std::vector<float> out, actions(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
    for (int pass = 0; pass < 2; ++pass) {
      env.reset({}, 11);
      for (int step = 0; step < 300; ++step) {
        for (std::size_t i = 0; i < actions.size(); ++i) {
          actions[i] = static_cast<float>(env.actionHigh()[i % env.actionDim()] * rng.uniform());
        }
        const StepResult& r = env.step(actions);
        out.insert(out.end(), r.observations.begin(), r.observations.end());
        out.insert(out.end(), r.outcomes.begin(), r.outcomes.end());
        for (const Obstacle& p : env.view(0).movers()) {
          out.push_back(static_cast<float>(p.center.x()));
          out.push_back(static_cast<float>(p.center.y()));
        }
      }
    }
    return out;
  };
  for (bool rounds : {false, true}) {
    const std::vector<float> one = run(1, rounds), two = run(2, rounds);
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(std::equal(one.begin(), one.end(), two.begin()))
        << "1 and 2 threads differ, rounds " << rounds;
  }
}

}  // namespace
}  // namespace jetbot_rl
