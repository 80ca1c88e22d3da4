// The forward speed limit near what the scan sees ahead (speed_limit/...): its path ahead from the
// robot's collision shapes, its cap on hand-made scans, its rules, and a Jetbot driven flat out
// at a wall that stops short of it behind the limit and hits it without.
#include <cmath>
#include <limits>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/speed_limit.h"
#include "jetbot_rl/tasks/observer_spec.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// A path ahead from x 0.05, y in [-0.07, 0.07]; stop at 0.1, full speed at 0.4.
SpeedLimitSpec testSpec() { return SpeedLimitSpec{0.05, 0.07, -0.07, 0.1, 0.4}; }

/// A 360-sample scan from -pi reading nothing but `range` at sample `k` (k degrees from -pi).
std::vector<float> scanWith(int k, float range) {
  std::vector<float> scan(360, kInf);
  scan[k] = range;
  return scan;
}

SpeedLimit limitOf(const SpeedLimitSpec& spec) {
  return SpeedLimit(spec, 360, -kPi, 2 * kPi / 360, 0.15);
}

TEST(SpeedLimit, RampsFromTheStopToTheSlowDistanceAheadOfTheFront) {
  const SpeedLimit limit = limitOf(testSpec());
  // Straight ahead (sample 180): distance from the front = range - 0.05.
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(180, 1.0f).data(), 0.6), 0.6);
  EXPECT_NEAR(limit.cap(scanWith(180, 0.45f).data(), 0.6), 0.6, 1e-6);
  EXPECT_NEAR(limit.cap(scanWith(180, 0.30f).data(), 0.6), 0.6 * (0.25 - 0.1) / 0.3, 1e-6);
  EXPECT_NEAR(limit.cap(scanWith(180, 0.15f).data(), 0.6), 0.0, 1e-6);
  EXPECT_NEAR(limit.clearAhead(scanWith(180, 0.30f).data()), 0.25, 1e-6);
  // From a known clear-ahead distance (the deploy node's one pass): the same ramp.
  const std::vector<float> near = scanWith(180, 0.30f);
  EXPECT_DOUBLE_EQ(limit.capAt(limit.clearAhead(near.data()), 0.6), limit.cap(near.data(), 0.6));
  EXPECT_DOUBLE_EQ(limit.capAt(0.05, 0.6), 0.0);
  EXPECT_DOUBLE_EQ(limit.capAt(0.5, 0.6), 0.6);
  // Too close to measure ahead: as if at range_min, inside the stop distance.
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(180, -kInf).data(), 0.6), 0.0);
  // Nothing seen, or nothing known: no cap.
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(180, std::nanf("")).data(), 0.6), 0.6);
  EXPECT_TRUE(std::isinf(limit.clearAhead(scanWith(180, kInf).data())));
}

TEST(SpeedLimit, OnlyWhatLiesInThePathAheadCounts) {
  const SpeedLimit limit = limitOf(testSpec());
  // 0.2 m at 30 degrees left: y 0.1, beside the path (0.07) however near.
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(210, 0.2f).data(), 0.6), 0.6);
  // 0.2 m at 15 degrees left: y 0.052, x 0.193, in the path 0.143 ahead of the front.
  EXPECT_NEAR(limit.cap(scanWith(195, 0.2f).data(), 0.6),
              0.6 * (0.2 * std::cos(kPi / 12) - 0.05 - 0.1) / 0.3, 1e-5);
  // Behind (sample 0 is -pi) and beside the body, short of the front: no cap.
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(0, 0.2f).data(), 0.6), 0.6);
  EXPECT_DOUBLE_EQ(limit.cap(scanWith(180 + 80, 0.06f).data(), 0.6), 0.6);
  // The path is the robot's, wherever the scanner sits: shifted right, the left reading is out.
  SpeedLimitSpec shifted = testSpec();
  shifted.left = 0.02;
  shifted.right = -0.12;
  EXPECT_DOUBLE_EQ(limitOf(shifted).cap(scanWith(195, 0.2f).data(), 0.6), 0.6);
}

TEST(SpeedLimit, ThePathAheadIsTheRobotsCollisionShapesSeenFromItsScanner) {
  // urdf/jetbot_lidar.urdf: the body box reaches x 0.03 and the wheels y +-0.06875; the scanner
  // sits 0.03 m behind the root link origin.
  const RobotModelConstPtr robot = test::lidarJetbot();
  EXPECT_NEAR(robot->frontReach(), 0.03, 1e-9);
  EXPECT_NEAR(robot->halfWidth(), 0.05625 + 0.0125, 1e-9);
  ScannerSpec scanner = test::fullTurnScanner(0.15, 3.5);
  scanner.link = "lidar_link";
  scanner.pose_in_body.translation() = Eigen::Vector3d(-0.03, 0.0, 0.075);
  SpeedLimitConfig config;
  config.enabled = true;
  const SpeedLimitSpec spec = makeSpeedLimitSpec(config, *robot, scanner);
  EXPECT_NEAR(spec.front, 0.06, 1e-9);
  EXPECT_NEAR(spec.left, 0.06875 + 0.005, 1e-9);
  EXPECT_NEAR(spec.right, -0.06875 - 0.005, 1e-9);
  // A scanner turned from the root's x axis, or on a moving link, is refused by name.
  ScannerSpec turned = scanner;
  turned.pose_in_body.linear() = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()).matrix();
  EXPECT_THROW(
      {
        try {
          makeSpeedLimitSpec(config, *robot, turned);
        } catch (const ConfigError& e) {
          EXPECT_NE(std::string(e.what()).find("speed_limit/enabled"), std::string::npos);
          throw;
        }
      },
      ConfigError);
  ScannerSpec moving = scanner;
  moving.body = 1;
  EXPECT_THROW(makeSpeedLimitSpec(config, *robot, moving), ConfigError);
}

/// The config's validation refuses it with a ConfigError naming `field`.
void expectInvalid(const EnvConfig& c, const std::string& field) {
  try {
    validateConfig(c);
    ADD_FAILURE() << "accepted; expected an error naming " << field;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(SpeedLimit, BadSettingsAreRefusedByName) {
  EnvConfig c = test::scanningArenaConfig(1);
  c.action_space = ActionSpace::kTwist;
  c.speed_limit.enabled = true;
  EXPECT_NO_THROW(validateConfig(c));
  c.speed_limit.slow_distance = c.speed_limit.stop_distance;
  expectInvalid(c, "speed_limit/slow_distance");
  c.speed_limit.slow_distance = 0.25;
  c.speed_limit.stop_distance = -0.1;
  expectInvalid(c, "speed_limit/stop_distance");
  c.speed_limit.stop_distance = 0.1;
  c.action_space = ActionSpace::kWheels;
  expectInvalid(c, "speed_limit/enabled");
  c.action_space = ActionSpace::kTwist;
  c.scan.enabled = false;
  expectInvalid(c, "speed_limit/enabled");
  c.speed_limit.enabled = false;  // deployed only needs the same
  c.speed_limit.deployed = true;
  expectInvalid(c, "speed_limit/deployed");
  c.scan.enabled = true;
  c.speed_limit.slow_distance = 0.05;
  expectInvalid(c, "speed_limit/slow_distance");
  // The contract's fields come together or not at all, and in order.
  ObserverSpec o;
  o.speed_limit_path = {0.06, 0.07, -0.07};
  EXPECT_THROW(checkFieldRules(o), ConfigError);
  o.speed_limit_distances = {0.4, 0.1};
  EXPECT_THROW(checkFieldRules(o), ConfigError);
  o.speed_limit_distances = {0.1, 0.4};
  EXPECT_NO_THROW(checkFieldRules(o));
}

TEST(SpeedLimit, AnEvaluationDrivesAPolicyAsItWasTrained) {
  const RobotModelConstPtr robot = test::lidarJetbot();  // half width 0.06875 m
  ObserverSpec trained;
  trained.speed_limit_path = {0.06, 0.074, -0.074};
  trained.speed_limit_distances = {0.05, 0.3};
  SpeedLimitConfig config;
  config.deployed = true;  // the training's setting: an evaluation applies it
  takeSpeedLimit(trained, *robot, config);
  EXPECT_TRUE(config.enabled);
  EXPECT_FALSE(config.deployed);
  EXPECT_EQ(config.stop_distance, 0.05);
  EXPECT_EQ(config.slow_distance, 0.3);
  EXPECT_NEAR(config.margin, 0.074 - 0.06875, 1e-12);  // the training's, not the default 5 mm
  // A path trained with a 2 cm margin from an off-centre scanner is the path evaluated.
  ScannerSpec scanner = test::fullTurnScanner(0.15, 3.5);
  scanner.pose_in_body.translation() = Eigen::Vector3d(-0.03, 0.01, 0.075);
  SpeedLimitConfig wide;
  wide.enabled = true;
  wide.margin = 0.02;
  const SpeedLimitSpec made = makeSpeedLimitSpec(wide, *robot, scanner);
  trained.speed_limit_path = {made.front, made.left, made.right};
  SpeedLimitConfig evaluated;
  takeSpeedLimit(trained, *robot, evaluated);
  EXPECT_NEAR(evaluated.margin, 0.02, 1e-12);
  const SpeedLimitSpec again = makeSpeedLimitSpec(evaluated, *robot, scanner);
  EXPECT_NEAR(again.left, made.left, 1e-12);
  EXPECT_NEAR(again.right, made.right, 1e-12);
  // A narrower path than this robot (another robot's checkpoint) leaves no margin, not a negative.
  trained.speed_limit_path = {0.06, 0.05, -0.05};
  takeSpeedLimit(trained, *robot, evaluated);
  EXPECT_EQ(evaluated.margin, 0.0);
  // Trained without one: none, whatever the files say.
  takeSpeedLimit(ObserverSpec(), *robot, config);
  EXPECT_FALSE(config.enabled);
}

/// A lidar Jetbot in a 4 x 4 m arena at its centre facing +x, flat out at the wall 2 m ahead
/// for 10 s behind `limit`; returns the gap between its front and the wall's face [m]
/// (`collided`: it touched; `spec`: the env's).
double gapAfterDrivingAtTheWall(const SpeedLimitConfig& limit, bool& collided, BatchSpec& spec) {
  EnvConfig c = test::smallConfig(1);
  c.world.arena_size = {4.0, 4.0};
  c.action_space = ActionSpace::kTwist;
  c.episode_length_s = 100.0;
  c.scan.range = {0.15, 3.5};
  c.speed_limit = limit;
  BatchedEnv env(test::lidarJetbot(), c);
  RootState s = env.view(0).rootState();
  s.position.head<2>().setZero();
  s.orientation = Eigen::Quaterniond::Identity();
  env.setRootState(0, s);
  collided = false;
  for (int k = 0; k < 600; ++k) {
    env.step({10.0f, 0.0f});  // beyond the bound: clamped to 0.6 m/s first
    collided = collided || env.view(0).collided();
  }
  spec = env.spec();
  const double wall_face = 2.0 - 0.5 * c.world.wall_thickness;
  return wall_face - (env.view(0).rootState().position.x() + test::lidarJetbot()->frontReach());
}

TEST(SpeedLimit, AJetbotFlatOutAtAWallStopsShortOfItBehindTheLimitAndHitsItWithout) {
  bool collided = false;
  BatchSpec spec;
  SpeedLimitConfig limit;
  limit.enabled = true;
  const double gap = gapAfterDrivingAtTheWall(limit, collided, spec);
  EXPECT_FALSE(collided);
  EXPECT_GT(gap, 0.05);  // near the stop distance (0.1): the cap falls to 0 there
  EXPECT_LT(gap, 0.15);
  // The checkpoint's contract carries it for the deploy node.
  ASSERT_EQ(spec.observer.speed_limit_path.size(), 3u);
  EXPECT_NEAR(spec.observer.speed_limit_path[0], 0.06, 1e-9);
  EXPECT_EQ(spec.observer.speed_limit_distances, (std::vector<double>{0.1, 0.25}));
  const double free_gap = gapAfterDrivingAtTheWall(SpeedLimitConfig(), collided, spec);
  EXPECT_TRUE(collided);
  EXPECT_LT(free_gap, 0.01);
  EXPECT_TRUE(spec.observer.speed_limit_path.empty());
  // Deployed only: the env drives into the wall as without, and its spec names the limit, which
  // an evaluation of the checkpoint then applies.
  SpeedLimitConfig deployed;
  deployed.deployed = true;
  EXPECT_LT(gapAfterDrivingAtTheWall(deployed, collided, spec), 0.01);
  EXPECT_TRUE(collided);
  EXPECT_EQ(spec.observer.speed_limit_distances, (std::vector<double>{0.1, 0.25}));
  SpeedLimitConfig evaluated;
  takeSpeedLimit(spec.observer, *test::lidarJetbot(), evaluated);
  EXPECT_TRUE(evaluated.enabled);
  EXPECT_FALSE(evaluated.deployed);
  EXPECT_NEAR(gapAfterDrivingAtTheWall(evaluated, collided, spec), gap, 1e-9);
  EXPECT_FALSE(collided);
}

}  // namespace
}  // namespace jetbot_rl
