#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {
namespace test {

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

inline EnvConfig smallConfig(int num_envs, int threads = 1) {
  EnvConfig c;
  c.num_envs = num_envs;
  c.num_threads = threads;
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

}  // namespace test
}  // namespace jetbot_rl
