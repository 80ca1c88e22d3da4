#include "jetbot_rl/ppo/input_history.h"

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

InputHistory::InputHistory(int num_envs, int obs_dim, int action_dim, int obs_length,
                           int action_length)
    : num_envs_(num_envs),
      obs_dim_(obs_dim),
      action_dim_(action_dim),
      obs_length_(obs_length),
      action_length_(action_length) {
  if (num_envs < 1 || obs_dim < 1 || action_dim < 1 || obs_length < 1 || action_length < 0) {
    throw ConfigError("invalid history: " + std::to_string(num_envs) + " envs, obs_dim " +
                      std::to_string(obs_dim) + ", action_dim " + std::to_string(action_dim) +
                      ", obs_history_length " + std::to_string(obs_length) +
                      ", action_history_length " + std::to_string(action_length));
  }
  obs_ = torch::zeros({num_envs, obs_length, obs_dim});
  actions_ = torch::zeros({num_envs, action_length, action_dim});
}

std::unique_ptr<InputHistory> InputHistory::forConfig(const NetworkConfig& c, int num_envs,
                                                      int obs_dim, int action_dim) {
  if (!hasHistory(c)) return nullptr;
  return std::make_unique<InputHistory>(num_envs, obs_dim, action_dim, c.obs_history_length,
                                        c.action_history_length);
}

torch::Tensor InputHistory::pushed(const torch::Tensor& slots, const torch::Tensor& obs,
                                   const torch::Tensor& fresh) const {
  const torch::Tensor newest = obs.unsqueeze(1);
  const torch::Tensor shifted =
      torch::cat({newest, slots.slice(1, 0, obs_length_ - 1)}, 1);  // drops the oldest
  return torch::where(fresh.view({-1, 1, 1}), newest.expand_as(shifted), shifted);
}

torch::Tensor InputHistory::input(const torch::Tensor& obs_slots, const torch::Tensor& action_slots,
                                  const Normalize& normalize) const {
  const int64_t rows = obs_slots.size(0);
  const torch::Tensor obs =
      normalize(obs_slots.reshape({rows * obs_length_, obs_dim_})).reshape({rows, -1});
  if (action_length_ == 0) return obs;
  return torch::cat({obs, action_slots.reshape({rows, action_length_ * action_dim_})}, 1);
}

torch::Tensor InputHistory::push(const torch::Tensor& obs, const torch::Tensor& fresh,
                                 const Normalize& normalize) {
  obs_ = pushed(obs_, obs, fresh);
  actions_ = torch::where(fresh.view({-1, 1, 1}), torch::zeros_like(actions_), actions_);
  return input(obs_, actions_, normalize);
}

void InputHistory::pushActions(const torch::Tensor& actions) {
  if (action_length_ == 0) return;
  actions_ = torch::cat({actions.unsqueeze(1), actions_.slice(1, 0, action_length_ - 1)}, 1);
}

torch::Tensor InputHistory::peek(const torch::Tensor& rows, const torch::Tensor& obs,
                                 const torch::Tensor& fresh, const Normalize& normalize) const {
  const torch::Tensor slots = pushed(obs_.index_select(0, rows), obs, fresh);
  const torch::Tensor actions = actions_.index_select(0, rows);
  return input(slots, torch::where(fresh.view({-1, 1, 1}), torch::zeros_like(actions), actions),
               normalize);
}

}  // namespace ppo
}  // namespace jetbot_rl
