#include "jetbot_rl/ppo/policy_memory.h"

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/recurrent_memory.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

PolicyMemory::PolicyMemory(const NetworkConfig& config, const ActorCritic& model, int num_envs,
                           int obs_dim, int action_dim, bool with_critic)
    : num_envs_(num_envs),
      recurrent_(model->recurrent()),
      history_(InputHistory::forConfig(config, num_envs, obs_dim, action_dim)),
      fresh_(torch::ones({num_envs}, torch::kBool)) {
  if (config.image_frames > 1 && model->imageValues() > 0) {
    frames_ = std::make_unique<ImageFrames>(num_envs, model->imageValues() / config.image_frames,
                                            config.image_frames);
  }
  if (recurrent_) {
    state_ = model->initialState(num_envs);
    if (!with_critic) state_.critic = torch::Tensor();
  }
}

void PolicyMemory::reset(const std::vector<std::uint32_t>& envs) {
  bool* fresh = fresh_.data_ptr<bool>();
  for (std::uint32_t e : envs) {
    if (e >= static_cast<std::uint32_t>(num_envs_)) {
      throw InputError("memory: env " + std::to_string(e) + " of " + std::to_string(num_envs_));
    }
    fresh[e] = true;
  }
}

void PolicyMemory::resetAll() { fresh_.fill_(true); }

torch::Tensor PolicyMemory::begin(const torch::Tensor& obs, const Normalize& normalize,
                                  const torch::Tensor& pixels) {
  torch::Tensor input = history_ ? history_->push(obs, fresh_, normalize) : normalize(obs);
  if (pixels.defined()) {
    input = torch::cat({input, frames_ ? frames_->push(pixels, fresh_) : pixels}, -1);
  }
  if (recurrent_) {
    starts_ = fresh_.to(torch::kFloat);
    state_.actor = startOver(state_.actor, starts_);
    if (state_.critic.defined()) state_.critic = startOver(state_.critic, starts_);
  }
  return input;
}

void PolicyMemory::end(const torch::Tensor& actions) {
  if (history_) history_->pushActions(actions);
  fresh_.zero_();
}

torch::Tensor PolicyMemory::peekInput(const torch::Tensor& rows, const torch::Tensor& obs,
                                      const torch::Tensor& fresh, const Normalize& normalize,
                                      const torch::Tensor& pixels) const {
  const torch::Tensor input =
      history_ ? history_->peek(rows, obs, fresh, normalize) : normalize(obs);
  if (!pixels.defined()) return input;
  return torch::cat({input, frames_ ? frames_->peek(rows, pixels, fresh) : pixels}, -1);
}

torch::Tensor PolicyMemory::peekCriticState(const torch::Tensor& rows,
                                            const torch::Tensor& fresh) const {
  return startOver(state_.critic.index_select(0, rows), fresh);
}

}  // namespace ppo
}  // namespace jetbot_rl
