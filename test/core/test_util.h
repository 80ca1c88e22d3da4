#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace test {

/// The Jetbot\'s wheel radius and separation (urdf/jetbot.urdf) [m].
constexpr double kJetbotWheelRadius = 0.03;
constexpr double kJetbotWheelSeparation = 0.1125;

inline std::string jetbotUrdfText() {
  std::ifstream file(JETBOT_URDF);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

inline RobotModelConstPtr jetbot() {
  static const RobotModelConstPtr model = RobotModel::fromUrdfFile(JETBOT_URDF);
  return model;
}

/// Resolves package://jetbot_rl/ into the source tree, as the ROS adapter's resolver would.
inline std::string testResolver(const std::string& uri) {
  const std::string prefix = "package://jetbot_rl/";
  if (uri.compare(0, prefix.size(), prefix) != 0) return "";
  return std::string(JETBOT_RL_SOURCE_DIR) + "/" + uri.substr(prefix.size());
}

inline std::string tribotUrdfText() {
  std::ifstream file(TRIBOT_URDF);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// urdf/examples/tribot.urdf: massless root, rotated wheel frames, no <limit>, box caster, mesh.
inline RobotModelConstPtr tribot() {
  static const RobotModelConstPtr model = RobotModel::fromUrdfFile(TRIBOT_URDF, testResolver);
  return model;
}

/// urdf/jetbot_lidar.urdf: the Jetbot with a 360-sample laser scanner, loaded once.
inline RobotModelConstPtr lidarJetbot() {
  static const RobotModelConstPtr model =
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_lidar.urdf");
  return model;
}

/// `text` with its one occurrence of `from` replaced by `to` (a failure when absent).
inline std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test fixture: '" << from << "' not found";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Writes `text` to a file of that name in gtest's temporary folder; returns its path.
inline std::string writeTempFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// A scanner of 360 samples, one a degree over a full turn from -pi, reading `range_min` to
/// `range_max` [m], no noise.
/// A Gazebo world file `name` (in the temporary folder) of SDF `version` holding `body`; its path.
inline std::string sdfWorld(const std::string& name, const std::string& body,
                            const std::string& version = "1.6") {
  return writeTempFile(name, "<?xml version=\"1.0\"?>\n<sdf version=\"" + version +
                                 "\">\n<world name=\"w\">\n" + body + "</world>\n</sdf>\n");
}

inline ScannerSpec fullTurnScanner(double range_min, double range_max) {
  constexpr double pi = 3.14159265358979323846;
  ScannerSpec spec;
  spec.samples = 360;
  spec.min_angle = -pi;
  spec.max_angle = pi - 2 * pi / 360;
  spec.range_min = range_min;
  spec.range_max = range_max;
  return spec;
}

inline EnvConfig smallConfig(int num_envs, int threads = 1) {
  EnvConfig c;
  c.num_envs = num_envs;
  c.num_threads = threads;
  return c;
}

/// The navigation tests' env: a 4 x 4 m arena, random starts, the base scanning 24 samples out
/// to 3.5 m.
inline EnvConfig scanningArenaConfig(int num_envs, int threads = 1) {
  EnvConfig c = smallConfig(num_envs, threads);
  c.world.arena_size = {4.0, 4.0};
  c.world.random_start = true;
  c.scan.link = "base_link";
  c.scan.samples = 24;
  c.scan.range = {0.05, 3.5};
  return c;
}

/// The navigation task with its defaults; with `path`, following a global path (nav/path).
inline std::unique_ptr<Task> navigationTask(bool path = false) {
  TaskConfig t;
  t.task = TaskKind::kNavigation;
  t.navigation.path = path;
  return makeTask(t);
}

/// The tribot's dofs, with the limits its URDF lacks given as parameters.
/// A navigation batch of `robot` with config `c` is refused with a ConfigError naming `field`.
inline void expectRefused(const RobotModelConstPtr& robot, const EnvConfig& c,
                          const std::string& field) {
  try {
    BatchedEnv env(robot, c, navigationTask());
    ADD_FAILURE() << "accepted; expected an error naming " << field;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

inline EnvConfig tribotConfig(int num_envs, int threads = 1) {
  EnvConfig c = smallConfig(num_envs, threads);
  c.dof_names = {"wheel_left_joint", "wheel_right_joint"};
  c.wheel_velocity_limit = 8.0;  // [rad/s]
  c.effort_limit = 0.3;          // [N m]
  return c;
}

/// The same (left, right) targets for every env.
inline std::vector<float> uniformActions(const BatchedEnv& env, float left, float right) {
  std::vector<float> a;
  for (int e = 0; e < env.numEnvs(); ++e) {
    a.push_back(left);
    a.push_back(right);
  }
  return a;
}

/// Body-frame COM velocity [m/s] and yaw rate [rad/s] of env 0, averaged.
struct Averages {
  Eigen::Vector3d body_velocity = Eigen::Vector3d::Zero();
  double yaw_rate = 0.0;
};

/// Drives env 0 with (left, right) targets [rad/s] for `settle` steps, then averages its
/// body-frame velocity and yaw rate over `measure` steps.
inline Averages drive(BatchedEnv& env, float left, float right, int settle, int measure) {
  const auto actions = uniformActions(env, left, right);
  for (int s = 0; s < settle; ++s) env.step(actions);
  Averages avg;
  for (int s = 0; s < measure; ++s) {
    env.step(actions);
    const RootState state = env.view(0).rootState();
    avg.body_velocity += state.comLinearVelocityBody();
    avg.yaw_rate += state.angular_velocity.z();
  }
  avg.body_velocity /= measure;
  avg.yaw_rate /= measure;
  return avg;
}

/// Reproducible pseudo-random targets in [-20, 20] rad/s from a stream of `seed`.
inline std::vector<float> seededActions(int num_envs, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<float> a(static_cast<std::size_t>(num_envs) * 2);
  for (float& x : a) x = static_cast<float>(40.0 * rng.uniform() - 20.0);
  return a;
}

/// Length of a polyline [m].
inline double pathLength(const std::vector<Eigen::Vector2d>& path) {
  double l = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) l += (path[i] - path[i - 1]).norm();
  return l;
}

/// Reproducible pseudo-random targets in [-25, 25] rad/s (some beyond the limit) for step `step`.
inline std::vector<float> randomActions(int num_envs, int step, unsigned salt = 0) {
  std::vector<float> a(static_cast<size_t>(num_envs) * 2);
  Rng rng(1000 + salt, static_cast<std::uint64_t>(step));
  for (auto& x : a) x = static_cast<float>(50.0 * rng.uniform() - 25.0);
  return a;
}

inline bool bitEqual(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/// Observations of env `env` only.
inline std::vector<float> envObs(const BatchedEnv& batch, int env) {
  const auto& o = batch.state().observations;
  return std::vector<float>(o.begin() + env * batch.obsDim(),
                            o.begin() + (env + 1) * batch.obsDim());
}

/// Puts row `row`'s robot at `p` [m] heading `yaw` [rad], at rest.
inline void place(BatchedEnv& env, int row, const Eigen::Vector2d& p, double yaw) {
  RootState s = env.view(row).rootState();
  s.position.head<2>() = p;
  s.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  s.com_linear_velocity.setZero();
  s.angular_velocity.setZero();
  env.setRootState(row, s);
}

}  // namespace test
}  // namespace jetbot_rl
