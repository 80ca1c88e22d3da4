#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/checkpoint_meta.h"
#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/**
 * A trained policy for playing: the checkpoint's model and normaliser, acting with the mean.
 * A policy with memory (history, RNN) keeps it per env: the caller starts an env's memory over
 * with resetMemory() when its episode (or, on a robot, its command) starts.
 *
 * Its networks live behind a pointer (policy_model.h), so that a program playing a policy does
 * not parse libtorch's headers.
 */
class Policy {
 public:
  /// Loads `checkpoint` (Error naming the file when it cannot); the action limits are the
  /// checkpoint's (a checkpoint of format 1 has none: call setActionLimits()).
  explicit Policy(const std::string& checkpoint);
  ~Policy();
  Policy(Policy&&) noexcept;
  Policy& operator=(Policy&&) noexcept;

  /// Sets the env's action limits (from EnvSpec); ConfigError when they do not fit the model.
  /// Returns "" or, when the checkpoint holds other limits, a line naming both (for a warning:
  /// the policy's normalised actions then span the env's range, not the one it was trained on).
  std::string setActionLimits(const std::vector<float>& low, const std::vector<float>& high);
  /// Makes the policy act on an env of spec `env`: ConfigError naming the field when a field the
  /// policy is bound to differs from the checkpoint's (task, sizes, names, scan beams; fields
  /// the checkpoint does not hold are not compared); the env's action limits
  /// (setActionLimits()); returns a warning for every other field that differs (bounds, control
  /// step, episode length, ...).
  std::vector<std::string> fitTo(const BatchSpec& env);
  /// Deterministic actions for `num_envs` observations (num_envs x obs_dim, row-major) into
  /// `out` (num_envs x action_dim, env units, e.g. rad/s); the memory steps as in training
  /// (PolicyMemory). Another num_envs than the last call's starts every env's memory over.
  /// A policy that observes a camera image refuses it (InputError): the overload below.
  void act(const std::vector<float>& observations, int num_envs, std::vector<float>& out);
  /// The same for a policy that observes a camera image (observesImage()): `images` holds
  /// num_envs rgb8 images of imageWidth() x imageHeight(), row-major from the top left (the
  /// batch's images_rgb); a policy without ignores them. InputError on a wrong size.
  void act(const std::vector<float>& observations, const std::vector<std::uint8_t>& images,
           int num_envs, std::vector<float>& out);
  /// True when the policy observes a camera image (its contract's camera_image).
  bool observesImage() const { return !meta_.spec.observer.camera_image.empty(); }
  int imageWidth() const { return meta_.spec.observer.camera_width; }    ///< [px]
  int imageHeight() const { return meta_.spec.observer.camera_height; }  ///< [px]
  /// Starts the memory of `envs` over: their next act() is an episode's first step.
  void resetMemory(const std::vector<std::uint32_t>& envs);
  /// Starts every env's memory over.
  void resetMemory();
  /// True when the policy has memory (a history or an RNN).
  bool hasMemory() const { return ppo::hasMemory(meta_.config); }

  /// Writes the policy as a TorchScript module (the observation normaliser, the mean action, the
  /// memory and the squashing and scaling to the action limits inside) that libtorch or PyTorch
  /// load without this package: forward(obs [B, obs_dim] float32) -> actions [B, action_dim]
  /// (env units); with memory forward(obs, hidden [B, H]) -> (actions, hidden) and
  /// initial_hidden(batch) -> zeros [B, H] (an env's row set to it starts its memory over).
  /// `spec` gives the names and control step, stored in the file's extra file "meta.yaml".
  /// Needs action limits; throws Error naming the file when it cannot be written.
  void exportTorchScript(const std::string& path, const BatchSpec& spec) const;

  const CheckpointMeta& meta() const { return meta_; }
  int obsDim() const { return meta_.obs_dim; }
  int actionDim() const { return meta_.action_dim; }

 private:
  struct Model;  // the networks, the action scaler and the memory (policy_model.h)

  CheckpointMeta meta_;
  std::unique_ptr<Model> model_;
};

/// Sets how many threads libtorch uses within an operation (a robot's policy acts on one small
/// batch: 1 spares the pool's hand-offs), without the caller including libtorch.
void setTorchThreads(int threads);

}  // namespace ppo
}  // namespace jetbot_rl
