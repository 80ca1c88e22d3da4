#include "jetbot_rl/ppo/action_scaler.h"

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

ActionScaler::ActionScaler(const std::vector<float>& low, const std::vector<float>& high,
                           ActionSquash squash)
    : tanh_(squash == ActionSquash::kTanh) {
  if (low.empty() || low.size() != high.size()) {
    throw ConfigError("action limits: action_low has " + std::to_string(low.size()) +
                      " values and action_high " + std::to_string(high.size()));
  }
  for (std::size_t i = 0; i < low.size(); ++i) {
    if (!std::isfinite(low[i]) || !std::isfinite(high[i]) || !(low[i] < high[i])) {
      throw ConfigError("action limits of dimension " + std::to_string(i) + ": [" +
                        std::to_string(low[i]) + ", " + std::to_string(high[i]) +
                        "] must be finite with low < high");
    }
  }
  const torch::Tensor lo = torch::tensor(low, torch::kFloat);
  const torch::Tensor hi = torch::tensor(high, torch::kFloat);
  center_ = 0.5 * (lo + hi);
  half_range_ = 0.5 * (hi - lo);
}

torch::Tensor ActionScaler::squash(const torch::Tensor& actions) const {
  return tanh_ ? torch::tanh(actions) : torch::clamp(actions, -1.0, 1.0);
}

torch::Tensor ActionScaler::toEnv(const torch::Tensor& actions) const {
  return center_ + half_range_ * squash(actions);
}

void ActionScaler::toEnv(const torch::Tensor& actions, std::vector<float>& out) const {
  const torch::Tensor env = toEnv(actions).contiguous();
  out.assign(env.data_ptr<float>(), env.data_ptr<float>() + env.numel());
}

}  // namespace ppo
}  // namespace jetbot_rl
