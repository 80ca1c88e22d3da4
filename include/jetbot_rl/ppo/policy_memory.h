#pragma once

#include <torch/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/ppo/actor_critic.h"
#include "jetbot_rl/ppo/image_frames.h"
#include "jetbot_rl/ppo/input_history.h"
#include "jetbot_rl/ppo/network_config.h"

namespace torch {
namespace jit {
struct Module;
}  // namespace jit
}  // namespace torch

namespace jetbot_rl {
namespace ppo {

/**
 * A policy's memory of every env of a batch (rsl_rl's Memory): its observation and action
 * history (InputHistory), its frame stack (ImageFrames) and its recurrent states, and which envs
 * start over at their next step.
 * The one place they are stepped, for learning (Ppo: the actor's and the critic's states) and
 * acting (Policy: the actor's); the TorchScript export writes the same steps
 * (memoryScript()). Without memory (hasMemory false) a step is the normalised
 * observation.
 */
class PolicyMemory {
 public:
  /// For `model` (its recurrent layers) and `num_envs` envs, all starting over; `with_critic`
  /// keeps the critic's recurrent state too (learning).
  PolicyMemory(const NetworkConfig& config, const ActorCritic& model, int num_envs, int obs_dim,
               int action_dim, bool with_critic);

  int numEnvs() const { return num_envs_; }
  bool recurrent() const { return recurrent_; }

  /// rsl_rl's reset(dones): these envs start over at their next step (an episode ended, a new
  /// command or goal came); InputError for an env out of range.
  void reset(const std::vector<std::uint32_t>& envs);
  /// Every env starts over at its next step.
  void resetAll();

  /// Begins a step of every env with its raw observation `obs` [N, obs_dim]: the history pushed
  /// (an env that starts over holds its first observation in every slot and zero actions), the
  /// recurrent states zeroed for the envs that start over. An image policy's camera images
  /// `pixels` [N, one image's values] (floats 0-255) follow, stacked with a frame stack. Returns
  /// the network input.
  torch::Tensor begin(const torch::Tensor& obs, const Normalize& normalize,
                      const torch::Tensor& pixels = {});
  /// [N] float, 1 for the envs that start over at the step begin() began.
  const torch::Tensor& starts() const { return starts_; }
  /// The recurrent states (undefined tensors without an RNN), which the model advances.
  MemoryState& state() { return state_; }
  const MemoryState& state() const { return state_; }
  /// Ends the step: `actions` [N, A] (normalised units) join the history; no env starts over.
  void end(const torch::Tensor& actions);

  /// [N] bool: the envs that start over at their next step.
  const torch::Tensor& fresh() const { return fresh_; }
  /// For values of states not acted on (a time-out's final observation, the observation after a
  /// rollout): the input envs `rows` [R] would get with `obs` [R, obs_dim] (and an image
  /// policy's `pixels` [R, one image's values]), starting over where `fresh` [R] (bool) is set.
  /// Nothing changes.
  torch::Tensor peekInput(const torch::Tensor& rows, const torch::Tensor& obs,
                          const torch::Tensor& fresh, const Normalize& normalize,
                          const torch::Tensor& pixels = {}) const;
  /// The critic's recurrent state of envs `rows` for such a value (zeroed where `fresh`).
  torch::Tensor peekCriticState(const torch::Tensor& rows, const torch::Tensor& fresh) const;

 private:
  int num_envs_;
  bool recurrent_;
  std::unique_ptr<InputHistory> history_;  // with a history
  std::unique_ptr<ImageFrames> frames_;    // with a frame stack
  MemoryState state_;                      // with an RNN
  torch::Tensor fresh_;                    // [N] bool
  torch::Tensor starts_;                   // [N] float, of the current step
};

/// The memory part of an exported policy: its hidden row's width and layout, the TorchScript
/// lines that step it (from `x`/`obs`/`hidden` to the actor MLP's input `x`), and the pieces of
/// the new hidden row; the RNN weights are registered as buffers of `module`.
struct MemoryScript {
  int64_t hidden_size = 0;
  std::string layout;                   ///< What the hidden row holds, for meta.yaml.
  std::string code;                     ///< Lines of forward() that make the input x.
  std::string rnn_code;                 ///< Then (after an image's features) the RNN's lines.
  std::vector<std::string> new_hidden;  ///< torch.cat() of these is the new hidden row.
  /// With a frame stack: its slots' first column in the hidden row (the images before the
  /// current one), else -1; imageScript() stacks them with the image.
  int64_t frames_at = -1;
};

/// The memory steps of PolicyMemory::begin() and end() for one policy, as TorchScript.
MemoryScript memoryScript(const NetworkConfig& config, const ActorCritic& model, int obs_dim,
                          int action_dim, torch::jit::Module& module);

}  // namespace ppo
}  // namespace jetbot_rl
