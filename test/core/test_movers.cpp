// Moving obstacles (movers/...): they walk straight to their waypoints at their speeds, keep out
// of the world, are seen by the scan, push the robot and end its episode as a mover collision;
// the same on any thread count; bad parameters are refused naming the field.
#include <cmath>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/scene/movers.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// The navigation arena (4 x 4 m, three boxes, two cylinders) with `people` people.
EnvConfig peopleConfig(int num_envs, int people, MoverRule rule, int threads = 1) {
  EnvConfig c = test::scanningArenaConfig(num_envs, threads);
  c.world.num_boxes = 3;
  c.world.num_cylinders = 2;
  c.world.cylinder_radius = {0.1, 0.2};
  c.movers.num_people = people;
  c.movers.rule = rule;
  c.movers.speed = {0.3, 1.0};
  return c;
}

TEST(Movers, WalkStraightToTheirWaypointsAtTheirSpeeds) {
  WorldConfig w;
  w.arena_size = {6.0, 6.0};
  w.random_start = true;
  const WorldModel world(w, 0.1);
  MoverConfig m;
  m.num_people = 3;
  m.num_carts = 2;
  m.rule = MoverRule::kStraight;
  MoverSet movers(m, world, 1, 7);
  EnvLayout layout;
  ASSERT_EQ(movers.reset(0, layout), 0);
  const double dt = 0.05;
  int arrivals = 0;
  std::vector<Eigen::Vector2d> last_waypoints;
  for (int k = 0; k < movers.count(); ++k) last_waypoints.push_back(movers.waypoint(0, k));
  for (int step = 0; step < 400; ++step) {
    std::vector<Eigen::Vector2d> before;
    for (const Obstacle& b : movers.bodies(0)) before.push_back(b.center);
    movers.plan(0, layout, Eigen::Vector2d(100, 100), dt);
    for (int i = 0; i < 6; ++i) movers.advance(0, dt / 6);
    for (int k = 0; k < movers.count(); ++k) {
      const Obstacle& b = movers.bodies(0)[k];
      ASSERT_TRUE(b.placed);
      const Eigen::Vector2d waypoint = movers.waypoint(0, k);
      if (waypoint != last_waypoints[k]) {  // it had arrived: a new one, drawn where it stood
        EXPECT_LE((last_waypoints[k] - before[k]).norm(),
                  std::max(0.5 * b.boundingRadius(), movers.speed(0, k) * dt) + 1e-9);
        last_waypoints[k] = waypoint;
        ++arrivals;
      }
      const Eigen::Vector2d moved = b.center - before[k];
      const Eigen::Vector2d to = waypoint - before[k];
      if (to.norm() <= movers.speed(0, k) * dt) {  // lands on it
        EXPECT_LT((b.center - waypoint).norm(), 1e-9) << "mover " << k << " overshot";
        continue;
      }
      // At its speed, along the straight line to its waypoint.
      EXPECT_NEAR(moved.norm(), movers.speed(0, k) * dt, 1e-9) << "mover " << k;
      EXPECT_NEAR(moved.normalized().dot(to.normalized()), 1.0, 1e-9);
      // Inside the walls.
      EXPECT_GE(world.clearance(b.center, nullptr), b.boundingRadius()) << "mover " << k;
      if (b.shape == Obstacle::Shape::kBox) {  // a cart faces where it goes
        EXPECT_NEAR(std::cos(b.yaw), to.normalized().x(), 1e-9);
        EXPECT_NEAR(std::sin(b.yaw), to.normalized().y(), 1e-9);
      }
    }
    for (int k = 0; k < movers.count(); ++k) {
      EXPECT_GE(movers.speed(0, k), m.speed[0]);
      EXPECT_LE(movers.speed(0, k), m.speed[1]);
    }
  }
  EXPECT_GT(arrivals, 5);  // they reach waypoints and head for new ones
}

TEST(Movers, SocialForceKeepsThemOffTheWorldAndEachOther) {
  BatchedEnv env(test::lidarJetbot(), peopleConfig(8, 10, MoverRule::kSocialForce),
                 test::navigationTask());
  const std::vector<float> stop(static_cast<std::size_t>(env.numEnvs()) * env.actionDim(), 0.0f);
  double closest_pair = 1e9, deepest_world = 1e9, fastest = 0.0;
  for (int step = 0; step < 300; ++step) {
    env.step(stop.data(), stop.size());
    for (int e = 0; e < env.numEnvs(); ++e) {
      const std::vector<Obstacle>& m = env.view(e).movers();
      const EnvLayout& layout = env.view(e).layout();
      for (std::size_t k = 0; k < m.size(); ++k) {
        if (!m[k].placed) continue;
        deepest_world = std::min(
            deepest_world, env.world()->clearance(m[k].center, &layout.obstacles) - m[k].radius);
        fastest = std::max(fastest, env.movers()->velocity(e, static_cast<int>(k)).norm() /
                                        env.movers()->speed(e, static_cast<int>(k)));
        for (std::size_t j = k + 1; j < m.size(); ++j) {
          closest_pair = std::min(closest_pair,
                                  (m[k].center - m[j].center).norm() - m[k].radius - m[j].radius);
        }
      }
    }
  }
  EXPECT_GT(deepest_world, -0.01);  // never into a wall or an obstacle (within a cm)
  EXPECT_GT(closest_pair, -0.05);   // people push each other off before they meet
  EXPECT_LE(fastest, 1.3 + 1e-9);   // Helbing's top speed: 1.3 x the walking speed
  EXPECT_GT(fastest, 0.9);          // and they do walk
}

TEST(Movers, TheScanSeesThemWhereTheyStand) {
  EnvConfig c = peopleConfig(4, 10, MoverRule::kSocialForce);
  c.scan.samples = 360;
  c.scan.angles = {-3.14159265358979323846, 3.14159265358979323846 * 179.0 / 180.0};
  BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
  const std::vector<float> stop(static_cast<std::size_t>(env.numEnvs()) * env.actionDim(), 0.0f);
  int differ = 0;
  for (int step = 0; step < 20; ++step) {
    env.step(stop.data(), stop.size());
    for (int e = 0; e < env.numEnvs(); ++e) {
      const EnvView view = env.view(e);
      // The scan of the env's physics pose against its world, obstacles and movers, cast here.
      const ScannerSpec& spec = *env.scanner();
      const LinkPose* link = nullptr;
      const std::vector<LinkPose> poses = view.linkPoses();
      for (const LinkPose& p : poses) {
        if (p.link == env.robot().bodies()[spec.body].link_name) link = &p;
      }
      ASSERT_NE(link, nullptr);
      Eigen::Isometry3d sensor = link->pose * spec.pose_in_body;
      sensor.translation() -= view.origin();
      Rng noise;
      std::vector<float> with(spec.samples), without(spec.samples);
      castScan(spec, env.world(), view.layout().obstacles, sensor, noise, with.data(),
               &view.movers());
      castScan(spec, env.world(), view.layout().obstacles, sensor, noise, without.data());
      for (int k = 0; k < spec.samples; ++k) {
        ASSERT_FLOAT_EQ(view.scan()[k], with[k]) << "env " << e << " beam " << k;
        if (with[k] < without[k]) ++differ;
      }
    }
  }
  EXPECT_GT(differ, 100);  // the people hide parts of the world
}

/// One person walking at 1 m/s, blind to the robot, and the robot standing 1 m ahead of it on
/// its way (a walk of more than 1.5 m); `way`: the person's direction.
std::unique_ptr<BatchedEnv> personWalkingAtTheRobot(std::unique_ptr<Task> task,
                                                    Eigen::Vector2d& way) {
  EnvConfig c = test::scanningArenaConfig(1);
  c.world.arena_size = {6.0, 6.0};
  c.movers.num_people = 1;
  c.movers.person_radius = {0.2, 0.2};
  c.movers.speed = {1.0, 1.0};
  c.movers.rule = MoverRule::kStraight;
  c.movers.start_clearance = 0.0;
  auto env = std::make_unique<BatchedEnv>(test::lidarJetbot(), c, std::move(task));
  const std::vector<float> stop(env->actionDim(), 0.0f);
  for (int tries = 0; tries < 200; ++tries) {
    const Obstacle& p = env->view(0).movers()[0];
    if ((env->movers()->waypoint(0, 0) - p.center).norm() > 1.5) break;
    env->step(stop.data(), stop.size());
  }
  const Obstacle person = env->view(0).movers()[0];
  EXPECT_GT((env->movers()->waypoint(0, 0) - person.center).norm(), 1.5);
  way = (env->movers()->waypoint(0, 0) - person.center).normalized();
  RootState s = env->view(0).rootState();
  s.position.head<2>() = person.center + way;
  s.com_linear_velocity.setZero();
  s.angular_velocity.setZero();
  env->setRootState(0, s);
  return env;
}

TEST(Movers, AMoverWalkingIntoTheRobotEndsTheEpisodeAsAMoverCollision) {
  Eigen::Vector2d way;
  auto env = personWalkingAtTheRobot(test::navigationTask(), way);
  auto& task = dynamic_cast<NavigationTask&>(env->task());
  const Eigen::Vector2d robot = env->view(0).rootState().position.head<2>();
  task.setGoal(0, robot + 1.2 * Eigen::Vector2d(-way.y(), way.x()));  // out of the way
  const std::vector<float> stop(env->actionDim(), 0.0f);
  std::uint8_t outcome = 255;
  int steps = 0;
  while (steps < 200 && outcome == 255) {
    const StepResult& r = env->step(stop.data(), stop.size());
    ++steps;
    if (!r.reset_env_ids.empty()) outcome = r.outcomes[0];
  }
  EXPECT_EQ(outcome, static_cast<std::uint8_t>(Outcome::kCollisionMover));
  // When the person had walked the gap (1 m less both radii) at 1 m/s.
  const double gap = 1.0 - 0.2 - env->robot().footprintRadius();
  EXPECT_NEAR(steps * env->controlDt(), gap, 0.15);
}

TEST(Movers, AMoverPushesTheRobotAndIsNotPushed) {
  TaskConfig velocity;  // a task that ends no episode on a collision
  Eigen::Vector2d way;
  auto env = personWalkingAtTheRobot(makeTask(velocity), way);
  const Eigen::Vector2d robot = env->view(0).rootState().position.head<2>();
  const std::vector<float> stop(env->actionDim(), 0.0f);
  bool touched = false;
  const int steps = static_cast<int>(std::lround(1.0 / env->controlDt()));  // 1 s
  for (int step = 0; step < steps; ++step) {
    const Eigen::Vector2d before = env->view(0).movers()[0].center;
    const Eigen::Vector2d waypoint = env->movers()->waypoint(0, 0);
    env->step(stop.data(), stop.size());
    touched = touched || env->view(0).collided();
    const Eigen::Vector2d after = env->view(0).movers()[0].center;
    if ((waypoint - before).norm() > env->controlDt()) {  // not arriving: 1 m/s on its way
      EXPECT_NEAR((after - before).norm(), env->controlDt(), 1e-9) << "step " << step;
    }
  }
  EXPECT_TRUE(touched);
  // The robot went with the person: pushed along its way (the person walked 1 m, 0.3 m of it
  // after it met the robot).
  const Eigen::Vector2d moved = env->view(0).rootState().position.head<2>() - robot;
  EXPECT_GT(moved.dot(way), 0.15);
}

TEST(Movers, AMoverFarFromTheRobotLeavesNoBodyBehindInThePhysics) {
  // Far from the robot a mover is not moved in Bullet: where it was must not stay solid there.
  EnvConfig c = test::scanningArenaConfig(1);
  c.world.arena_size = {6.0, 6.0};
  c.movers.num_people = 1;
  c.movers.person_radius = {0.2, 0.2};
  c.movers.speed = {1.0, 1.0};
  c.movers.rule = MoverRule::kStraight;
  c.movers.start_clearance = 2.0;
  TaskConfig velocity;  // ends no episode on a contact
  BatchedEnv env(test::lidarJetbot(), c, makeTask(velocity));
  const std::vector<float> stop(env.actionDim(), 0.0f);
  const Eigen::Vector2d start = env.view(0).movers()[0].center;
  const auto robot = [&] { return Eigen::Vector2d(env.view(0).rootState().position.head<2>()); };
  const auto far = [&] {
    const Eigen::Vector2d now = env.view(0).movers()[0].center;
    return (now - start).norm() > 1.5 && (now - robot()).norm() > 2.5;
  };
  int steps = 0;
  for (; steps < 2000 && !far(); ++steps) env.step(stop.data(), stop.size());
  ASSERT_TRUE(far()) << "the person never walked away";
  // The robot where the person stood at the reset: nothing is there now.
  RootState s = env.view(0).rootState();
  s.position.head<2>() = start;
  s.com_linear_velocity.setZero();
  s.angular_velocity.setZero();
  env.setRootState(0, s);
  env.step(stop.data(), stop.size());
  EXPECT_FALSE(env.view(0).collided()) << "a contact with a person 1.5 m away";
}

TEST(Movers, TheSameOnAnyThreadCountAndAfterAReseed) {
  const auto run = [](int threads) {
    BatchedEnv env(test::lidarJetbot(), peopleConfig(6, 10, MoverRule::kSocialForce, threads),
                   test::navigationTask());
    std::vector<float> out;
    Rng actions(3);
    std::vector<float> a(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
    for (int step = 0; step < 200; ++step) {
      for (float& x : a) x = static_cast<float>(actions.uniform());
      const StepResult& r = env.step(a.data(), a.size());
      out.insert(out.end(), r.observations.begin(), r.observations.end());
      for (std::uint8_t o : r.outcomes) out.push_back(o);
    }
    env.reset({}, 11);
    for (const Obstacle& m : env.view(5).movers()) {
      out.push_back(static_cast<float>(m.center.x()));
      out.push_back(static_cast<float>(m.center.y()));
    }
    return out;
  };
  const std::vector<float> one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "value " << i;
}

TEST(Movers, BadParametersAreRefusedNamingTheField) {
  const auto refused = [](EnvConfig c, const std::string& field) {
    try {
      BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
      ADD_FAILURE() << field << ": accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  EnvConfig none = test::scanningArenaConfig(1);
  none.world = WorldConfig();
  none.movers.num_people = 3;
  refused(none, "movers/num_people");  // no world to walk in
  EnvConfig crowd = peopleConfig(1, 200, MoverRule::kSocialForce);
  refused(crowd, "movers/num_people");  // no room for them
  EnvConfig carts = peopleConfig(1, 0, MoverRule::kSocialForce);
  carts.movers.num_carts = 60;
  refused(carts, "movers/num_carts");
  EnvConfig fast = peopleConfig(1, 3, MoverRule::kSocialForce);
  fast.movers.speed = {0.5, 20.0};
  refused(fast, "movers/speed");
  EnvConfig backwards = peopleConfig(1, 3, MoverRule::kSocialForce);
  backwards.movers.speed = {1.0, 0.5};
  refused(backwards, "movers/speed");
  EnvConfig flat = peopleConfig(1, 3, MoverRule::kSocialForce);
  flat.movers.person_radius = {0.0, 0.2};
  refused(flat, "movers/person_radius");
  EnvConfig outside = peopleConfig(1, 3, MoverRule::kSocialForce);
  outside.movers.region = {5.0, 5.0, 6.0, 6.0};  // beyond the arena's walls
  refused(outside, "movers/region");
  EnvConfig upside_down = peopleConfig(1, 3, MoverRule::kSocialForce);
  upside_down.movers.region = {1.0, -1.0, 0.5, 1.0};
  refused(upside_down, "movers/region");
}

TEST(Movers, StayInTheirRegion) {
  EnvConfig c = peopleConfig(4, 3, MoverRule::kSocialForce);
  c.movers.region = {0.5, -1.8, 1.0, 1.8};  // a band across the arena
  BatchedEnv env(test::lidarJetbot(), c, test::navigationTask());
  const Eigen::AlignedBox2d band(Eigen::Vector2d(0.5, -1.8), Eigen::Vector2d(1.0, 1.8));
  const std::vector<float> stop(static_cast<std::size_t>(env.numEnvs()) * env.actionDim(), 0.0f);
  for (int e = 0; e < env.numEnvs(); ++e) {
    for (const Obstacle& m : env.view(e).movers()) EXPECT_TRUE(band.contains(m.center));
  }
  double farthest = 0.0;
  for (int step = 0; step < 200; ++step) {
    env.step(stop.data(), stop.size());
    for (int e = 0; e < env.numEnvs(); ++e) {
      for (int k = 0; k < env.movers()->count(); ++k) {
        EXPECT_TRUE(band.contains(env.movers()->waypoint(e, k))) << "env " << e;
        farthest = std::max(farthest, band.exteriorDistance(env.view(e).movers()[k].center));
      }
    }
  }
  EXPECT_LT(farthest, 1.0);  // pushed off each other and the robot, never far
}

}  // namespace
}  // namespace jetbot_rl
