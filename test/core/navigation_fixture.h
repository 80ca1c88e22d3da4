#pragma once

// A navigation task attached to a hand-made scanner, for the tests of the task and its observer.

#include <Eigen/Core>
#include <vector>

#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace test {

/// A task with 4 beams over an 8-sample scanner of range [0.1, 4] (beam i: samples 2i and
/// 2i + 1), for env 0, goal `goal`.
struct NavigationFixture {
  ScannerSpec scanner;
  NavigationTask task;
  std::vector<float> scan{1.0f, 9.0f, kNoReturn, 9.0f, kTooClose, 9.0f, 2.0f, 9.0f};
  float action[2] = {3.0f, -2.0f};

  explicit NavigationFixture(const Eigen::Vector2d& goal,
                             NavigationConfig config = NavigationConfig(),
                             NavigationTask::Variant variant = NavigationTask::Variant::kProgress)
      : task((config.beams = 4, config), variant) {
    scanner.samples = 8;
    scanner.min_angle = -3.14159265358979323846;  // a full turn, 45 degrees apart
    scanner.max_angle = 3.14159265358979323846 * 3 / 4;
    scanner.range_min = 0.1;
    scanner.range_max = 4.0;
    TaskContext context;
    context.scanner = &scanner;
    context.action_dim = 2;
    task.attach(context);
    task.resize(1);
    Rng rng(1);
    task.resetEnv(0, rng);
    task.setGoal(0, goal);
    sense(false);
  }
  void sense(bool collided) { task.sense(0, {scan.data(), collided, action}); }
  std::vector<float> observe(const RootState& s) {
    std::vector<float> obs(task.observationNames().size());
    task.observe(0, s, obs.data());
    return obs;
  }
};

}  // namespace test
}  // namespace jetbot_rl
