#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/checkpoint.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/step_result.h"

namespace jetbot_rl {
namespace ppo {

/// A trained policy for playing: the checkpoint's model and normaliser, acting with the mean.
class Policy {
 public:
  /// Loads `checkpoint` (Error naming the file when it cannot).
  explicit Policy(const std::string& checkpoint);

  /// Sets the env's action limits (from EnvSpec); ConfigError when they do not fit the model.
  void setActionLimits(const std::vector<float>& low, const std::vector<float>& high);
  /// Deterministic actions for `num_envs` observations (num_envs x obs_dim, row-major) into
  /// `out` (num_envs x action_dim, env units, e.g. rad/s).
  void act(const std::vector<float>& observations, int num_envs, std::vector<float>& out);

  /// Writes the policy as a TorchScript module (the observation normaliser, the mean action and
  /// the squashing and scaling to the action limits inside) that libtorch or PyTorch load without
  /// this package: forward(obs [B, obs_dim] float32) -> actions [B, action_dim] (env units).
  /// `spec` gives the names and control step, stored in the file's extra file "meta.yaml".
  /// Needs setActionLimits(); throws Error naming the file when it cannot be written.
  void exportTorchScript(const std::string& path, const BatchSpec& spec) const;

  const CheckpointMeta& meta() const { return meta_; }
  int obsDim() const { return meta_.obs_dim; }
  int actionDim() const { return meta_.action_dim; }

 private:
  CheckpointMeta meta_;
  ActorCritic model_{nullptr};
  ObsNormalizer normalizer_{nullptr};
  std::unique_ptr<ActionScaler> scaler_;
};

}  // namespace ppo
}  // namespace jetbot_rl
