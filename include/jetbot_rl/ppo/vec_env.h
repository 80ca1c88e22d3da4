#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {

/// What a learner needs to know about a batched env (the content of EnvSpec).
struct EnvInfo {
  int num_envs = 0;
  int obs_dim = 0;
  int action_dim = 0;
  std::vector<float> action_low, action_high;  ///< Per action dimension [env units, rad/s].
  double control_dt = 0.0;                     ///< [s]
  int max_episode_length = 0;                  ///< Control steps.
  std::string task;
  std::vector<std::string> observation_names;  ///< Per observation component; may be empty.
};

/// The batch after a step or a reset (the content of EnvStep).
struct EnvBatch {
  std::uint64_t step = 0;
  std::vector<float> observations;                  ///< num_envs x obs_dim, after auto-reset.
  std::vector<float> rewards;                       ///< num_envs
  std::vector<std::uint8_t> terminated, truncated;  ///< num_envs
  std::vector<std::uint32_t> reset_env_ids;         ///< Envs that ended and were reset.
  std::vector<float> final_observations;  ///< len(reset_env_ids) x obs_dim, before the reset.
};

/// Thrown by a VecEnv when asked to stop (e.g. Ctrl-C) while waiting.
class Interrupted : public Error {
 public:
  using Error::Error;
};

/// A batched env with auto-reset, as a learner sees it (implemented over ROS by RosVecEnv).
class VecEnv {
 public:
  virtual ~VecEnv() = default;
  virtual const EnvInfo& info() const = 0;
  /// Resets every env; `seed` >= 0 reseeds the env's random streams.
  virtual const EnvBatch& reset(std::int64_t seed) = 0;
  /// Applies num_envs x action_dim actions [env units] for one control step.
  virtual const EnvBatch& step(const std::vector<float>& actions) = 0;
  /// Resets the envs `ids` without stepping (their random streams continue); returns the state,
  /// in which only their observations changed (rewards etc. are those of the last step).
  virtual const EnvBatch& resetEnvs(const std::vector<std::uint32_t>& ids) = 0;
};

}  // namespace ppo
}  // namespace jetbot_rl
