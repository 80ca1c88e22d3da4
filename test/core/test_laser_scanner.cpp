// The laser scanner: beam lengths against hand-computed geometry, REP 117 out-of-range values,
// noise, and its configuration read from a Gazebo ray sensor block as Gazebo reads it.
#include <cmath>
#include <numeric>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

/// A scanner of `samples` beams over [min, max] with range [range_min, range_max], no noise.
ScannerSpec spec(int samples, double min, double max, double range_min = 0.05,
                 double range_max = 10.0) {
  ScannerSpec s;
  s.samples = samples;
  s.min_angle = min;
  s.max_angle = max;
  s.range_min = range_min;
  s.range_max = range_max;
  return s;
}

/// The sensor at (x, y, 0.1), heading `yaw`.
Eigen::Isometry3d sensorAt(double x, double y, double yaw = 0.0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, 0.1);
  p.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

Obstacle box(double x, double y, double hx, double hy, double yaw = 0.0) {
  Obstacle o;
  o.center = {x, y};
  o.half_extents = {hx, hy};
  o.yaw = yaw;
  o.height = 0.5;
  return o;
}

Obstacle cylinder(double x, double y, double r) {
  Obstacle o;
  o.shape = Obstacle::Shape::kCylinder;
  o.center = {x, y};
  o.radius = r;
  o.height = 0.5;
  return o;
}

float castOne(const std::vector<Obstacle>& obstacles, double angle,
              const WorldModel* world = nullptr, const ScannerSpec& s = spec(1, 0, 0),
              const Eigen::Isometry3d& at = sensorAt(0, 0)) {
  ScannerSpec one = s;
  one.samples = 1;
  one.min_angle = one.max_angle = angle;
  Rng noise(1);
  float range = 0;
  castScan(one, world, obstacles, at, noise, &range);
  return range;
}

TEST(LaserScanner, AWallAtOneMetreReadsOneMetre) {
  WorldConfig config;
  config.arena_size = {2.0, 4.0};  // inner faces at x = +-1 and y = +-2
  const WorldModel world(config, 0.1);
  EXPECT_NEAR(castOne({}, 0.0, &world), 1.0, 1e-4);
  EXPECT_NEAR(castOne({}, kPi, &world), 1.0, 1e-4);
  EXPECT_NEAR(castOne({}, kPi / 2, &world), 2.0, 1e-4);
  // From elsewhere, at an angle: the face x = 1 from (0.5, 0) at 60 degrees is 1 m away.
  EXPECT_NEAR(castOne({}, kPi / 3, &world, spec(1, 0, 0), sensorAt(0.5, 0.0)), 1.0, 1e-4);
}

TEST(LaserScanner, CylindersBoxesAndCornersAtTheirExactDistance) {
  EXPECT_NEAR(castOne({cylinder(2.0, 0.3, 0.5)}, 0.0), 2.0 - std::sqrt(0.25 - 0.09), 1e-4);
  EXPECT_NEAR(castOne({box(2.0, 0.0, 0.5, 0.5)}, 0.0), 1.5, 1e-4);
  // The corner (1.5, 1.5) of an axis-aligned box, and the corner of one turned by 45 degrees.
  EXPECT_NEAR(castOne({box(2.0, 2.0, 0.5, 0.5)}, kPi / 4), 1.5 * std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(castOne({box(2.0, 0.0, 0.5, 0.5, kPi / 4)}, 0.0), 2.0 - 0.5 * std::sqrt(2.0), 1e-4);
  // The nearest of several; one behind the sensor is not seen.
  EXPECT_NEAR(
      castOne({box(-1.0, 0.0, 0.2, 0.2), cylinder(3.0, 0.0, 0.5), box(2.0, 0.0, 0.1, 1.0)}, 0.0),
      1.9, 1e-4);
  // A beam above an obstacle misses it.
  Obstacle low = box(2.0, 0.0, 0.5, 0.5);
  low.height = 0.05;
  EXPECT_EQ(castOne({low}, 0.0), kNoReturn);
}

TEST(LaserScanner, OutOfRangeReadingsFollowRep117) {
  const ScannerSpec s = spec(1, 0, 0, 0.5, 1.0);
  EXPECT_EQ(castOne({box(2.0, 0.0, 0.5, 0.5)}, 0.0, nullptr, s), kNoReturn);  // 1.5 > range_max
  EXPECT_EQ(castOne({box(0.8, 0.0, 0.5, 0.5)}, 0.0, nullptr, s), kTooClose);  // 0.3 < range_min
  EXPECT_EQ(castOne({}, 0.0, nullptr, s), kNoReturn);                         // nothing at all
  EXPECT_EQ(finiteRange(kNoReturn, s), 1.0f);
  EXPECT_EQ(finiteRange(kTooClose, s), 0.5f);
  EXPECT_EQ(finiteRange(0.7f, s), 0.7f);
}

TEST(LaserScanner, MapCellsAreHitAtTheirEdge) {
  // 10 x 5 cells of 0.2 m; the obstacle column x = 7 (1.4 to 1.6 m) in the middle row.
  test::writePgm("scan_map.pgm",
                 {"..........", "..........", ".......#..", "..........", ".........."});
  WorldConfig config;
  config.map = test::writeMapYaml("scan_map.yaml", "scan_map.pgm",
                                  "resolution: 0.2\norigin: [-0.5, -0.5, 0.0]\nnegate: 0\n"
                                  "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const WorldModel world(config, 0.1);
  // The sensor at the env origin, which is (0.5, 0.5) in the map: the cell's left edge is at
  // map x 1.4, 0.9 m ahead.
  EXPECT_NEAR(castOne({}, 0.0, &world), 0.9, 1e-4);
  EXPECT_EQ(castOne({}, kPi, &world), kNoReturn);  // off the map's edge: nothing
}

TEST(LaserScanner, BeamsSpreadAsGazeboSpreadsThem) {
  WorldConfig config;
  config.arena_size = {2.0, 2.0};
  const WorldModel world(config, 0.1);
  const ScannerSpec s = spec(3, -kPi / 2, kPi / 2);
  EXPECT_NEAR(s.angleIncrement(), kPi / 2, 1e-12);
  std::vector<float> ranges(3);
  Rng noise(1);
  // Heading +y: the beams point along +x, +y and -x.
  castScan(s, &world, {box(0.5, 0.0, 0.1, 0.1)}, sensorAt(0, 0, kPi / 2), noise, ranges.data());
  EXPECT_NEAR(ranges[0], 0.4, 1e-4);
  EXPECT_NEAR(ranges[1], 1.0, 1e-4);
  EXPECT_NEAR(ranges[2], 1.0, 1e-4);
}

TEST(LaserScanner, NoiseHasItsMeanAndStandardDeviation) {
  ScannerSpec s = spec(1, 0, 0, 0.05, 10.0);
  s.noise_mean = 0.01;
  s.noise_std = 0.05;
  Rng noise(7);
  const int n = 20000;
  std::vector<double> values;
  for (int i = 0; i < n; ++i) {
    float r = 0;
    castScan(s, nullptr, {box(2.0, 0.0, 0.5, 0.5)}, sensorAt(0, 0), noise, &r);
    values.push_back(r);
  }
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double var = 0;
  for (double v : values) var += (v - mean) * (v - mean);
  const double std = std::sqrt(var / (n - 1));
  EXPECT_NEAR(mean, 1.51, 4 * 0.05 / std::sqrt(n));
  EXPECT_NEAR(std, 0.05, 0.0025);
}

TEST(LaserScanner, TheTribotsGazeboBlockGivesTheDefaultsAndParametersWin) {
  const auto robot = test::tribot();
  ASSERT_TRUE(robot->gazebo().ray);
  const auto s = resolveScanner(ScannerConfig(), *robot, 1.0 / 60.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->link, "base_scan");
  EXPECT_EQ(s->samples, 360);
  EXPECT_DOUBLE_EQ(s->min_angle, 0.0);
  EXPECT_DOUBLE_EQ(s->max_angle, 6.28319);
  EXPECT_DOUBLE_EQ(s->range_min, 0.12);
  EXPECT_DOUBLE_EQ(s->range_max, 3.5);
  EXPECT_DOUBLE_EQ(s->noise_std, 0.01);
  EXPECT_EQ(s->update_every, 12);  // 5 Hz at 60 control steps per second
  EXPECT_EQ(s->samples_from, "Gazebo");
  ScannerConfig config;
  config.samples = 24;
  config.range = {0.2, 2.0};
  config.noise_std = 0.0;
  config.update_every = 1;
  const auto o = resolveScanner(config, *robot, 1.0 / 60.0);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->samples, 24);
  EXPECT_EQ(o->samples_from, "scan/samples");
  EXPECT_DOUBLE_EQ(o->range_max, 2.0);
  EXPECT_DOUBLE_EQ(o->max_angle, 6.28319);  // still Gazebo's
  EXPECT_EQ(o->noise_std, 0.0);
  config.enabled = false;
  EXPECT_FALSE(resolveScanner(config, *robot, 1.0 / 60.0));
}

TEST(LaserScanner, ARobotWithoutABlockHasNoScannerUnlessALinkIsGiven) {
  EXPECT_FALSE(resolveScanner(ScannerConfig(), *test::jetbot(), 1.0 / 60.0));
  ScannerConfig config;
  config.link = "base_link";
  const auto s = resolveScanner(config, *test::jetbot(), 1.0 / 60.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->samples, 360);
  EXPECT_NEAR(s->angleIncrement(), 2 * kPi / 360, 1e-12);
  EXPECT_DOUBLE_EQ(s->range_max, 3.5);
  EXPECT_EQ(s->update_every, 1);
}

TEST(LaserScanner, BadValuesAreRefusedNamingTheFieldAndWhereTheyCameFrom) {
  const auto error = [](const ScannerConfig& config, const RobotModel& robot) -> std::string {
    try {
      validateConfig(config);  // as the env does, once, before it resolves its scanner
      resolveScanner(config, robot, 1.0 / 60.0);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "accepted";
  };
  ScannerConfig config;
  config.link = "no_such_link";
  EXPECT_NE(error(config, *test::jetbot()).find("scan/link = 'no_such_link'"), std::string::npos);
  config = ScannerConfig();
  config.angles = {1.0, 1.0};
  EXPECT_NE(error(config, *test::tribot()).find("scan/angles = [1, 1]"), std::string::npos);
  config = ScannerConfig();
  config.range = {2.0, 1.0};
  EXPECT_NE(error(config, *test::tribot()).find("scan/range = [2, 1]"), std::string::npos);
  config = ScannerConfig();
  config.angles = {1.0};
  EXPECT_NE(error(config, *test::tribot()).find("scan/angles = [1]"), std::string::npos);
  // A Gazebo block with no beams: named, with its source.
  const std::string urdf =
      test::replaceOnce(test::tribotUrdfText(), "<samples>360</samples>", "<samples>0</samples>");
  const auto robot = RobotModel::fromUrdfString(urdf, test::testResolver);
  const std::string e = error(ScannerConfig(), *robot);
  EXPECT_NE(e.find("scan/samples = 0"), std::string::npos) << e;
  EXPECT_NE(e.find("Gazebo ray sensor 'tribot_lds'"), std::string::npos) << e;
}

}  // namespace
}  // namespace jetbot_rl
