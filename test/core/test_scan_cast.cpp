// castScan's beam windows lose nothing: on random scenes (boxes and cylinders near and far, some
// around the sensor, a tilted or turned scanner, full turns and partial fans, one beam), every
// range equals, bit for bit, what testing every beam against every obstacle gives.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "sensors/scan_rays.h"

namespace jetbot_rl {
namespace {

/// Every beam against every obstacle: the definition castScan must reproduce (no noise).
std::vector<float> everyBeamAgainstEveryObstacle(const ScannerSpec& spec,
                                                 const std::vector<Obstacle>& obstacles,
                                                 const Eigen::Isometry3d& sensor) {
  std::vector<float> ranges(spec.samples, kNoReturn);
  for (int k = 0; k < spec.samples; ++k) {
    const double angle = spec.min_angle + k * spec.angleIncrement();
    const Eigen::Vector3d d =
        sensor.linear() * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    double best = spec.range_max;
    for (const Obstacle& ob : obstacles) {
      best = ob.shape == Obstacle::Shape::kBox ? rayBox(sensor.translation(), d, ob, best)
                                               : rayCylinder(sensor.translation(), d, ob, best);
    }
    if (best < spec.range_max) {
      ranges[k] = best < spec.range_min ? kTooClose : static_cast<float>(best);
    }
  }
  return ranges;
}

TEST(CastScan, ItsBeamWindowsGiveWhatEveryBeamAgainstEveryObstacleGives) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * u(gen); };
  const std::vector<std::pair<int, std::pair<double, double>>> fans{
      {360, {-kPi, kPi - 2 * kPi / 360}},
      {24, {-kPi, 2.87979}},
      {100, {-1.0, 1.2}},
      {1, {0.3, 0.3}},
      {720, {-kPi, kPi}}};
  int scenes = 0, hits = 0;
  for (const auto& [samples, angles] : fans) {
    ScannerSpec spec;
    spec.samples = samples;
    spec.min_angle = angles.first;
    spec.max_angle = angles.second;
    spec.range_min = 0.12;
    spec.range_max = 3.5;
    for (int scene = 0; scene < 60; ++scene, ++scenes) {
      std::vector<Obstacle> obstacles;
      const int count = 1 + static_cast<int>(u(gen) * 120);
      for (int i = 0; i < count; ++i) {
        Obstacle ob;
        ob.shape = u(gen) < 0.5 ? Obstacle::Shape::kBox : Obstacle::Shape::kCylinder;
        ob.center = Eigen::Vector2d(uniform(-5, 5), uniform(-5, 5));
        ob.yaw = uniform(-kPi, kPi);
        ob.half_extents = Eigen::Vector2d(uniform(0.01, 0.4), uniform(0.01, 0.4));
        ob.radius = uniform(0.01, 0.3);
        ob.height = uniform(0.05, 0.5);
        ob.placed = u(gen) < 0.95;
        obstacles.push_back(ob);
      }
      // Now and then the sensor stands in an obstacle's bounding circle.
      if (scene % 7 == 0) obstacles[0].center = Eigen::Vector2d(0.05, -0.02);
      const double tilt = scene % 3 == 0 ? 0.0 : uniform(0.0, 0.3);
      Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
      sensor.translation() << uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(0.03, 0.2);
      sensor.linear() =
          (Eigen::AngleAxisd(uniform(-kPi, kPi), Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(tilt,
                             Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), 0.0).normalized()))
              .toRotationMatrix();
      std::vector<float> fast(samples);
      Rng noise(1);
      castScan(spec, nullptr, obstacles, sensor, noise, fast.data());
      std::vector<Obstacle> placed;
      for (const Obstacle& ob : obstacles) {
        if (ob.placed) placed.push_back(ob);
      }
      const std::vector<float> reference = everyBeamAgainstEveryObstacle(spec, placed, sensor);
      for (int k = 0; k < samples; ++k) {
        ASSERT_EQ(std::memcmp(&fast[k], &reference[k], sizeof(float)), 0)
            << "beam " << k << " of " << samples << ", scene " << scene << ": " << fast[k]
            << " instead of " << reference[k];
        hits += reference[k] != kNoReturn;
      }
    }
  }
  EXPECT_EQ(scenes, 300);
  EXPECT_GT(hits, 10000);  // the scenes are not empty
}

}  // namespace
}  // namespace jetbot_rl
