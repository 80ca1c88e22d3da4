#include "jetbot_rl/ppo/policy.h"

#include <torch/torch.h>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {

Policy::Policy(const std::string& checkpoint) : meta_(readCheckpointMeta(checkpoint)) {
  const PpoConfig& c = meta_.config;
  model_ = ActorCritic(meta_.obs_dim, meta_.action_dim, c.actor_hidden_dims, c.critic_hidden_dims,
                       c.activation, c.init_noise_std);
  normalizer_ = ObsNormalizer(meta_.obs_dim, c.normalize_observations);
  loadPolicy(checkpoint, model_, normalizer_);
  model_->eval();
}

void Policy::setActionLimits(const std::vector<float>& low, const std::vector<float>& high) {
  if (static_cast<int>(low.size()) != actionDim()) {
    throw ConfigError("the env has " + std::to_string(low.size()) +
                      " action dimensions; the policy was trained for " +
                      std::to_string(actionDim()));
  }
  scaler_ = std::make_unique<ActionScaler>(low, high, meta_.config.action_squash);
}

void Policy::act(const std::vector<float>& observations, int num_envs, std::vector<float>& out) {
  if (!scaler_) throw Error("Policy::act before setActionLimits");
  if (static_cast<int>(observations.size()) != num_envs * obsDim()) {
    throw InputError("expected " + std::to_string(num_envs * obsDim()) + " observations, got " +
                     std::to_string(observations.size()));
  }
  torch::NoGradGuard no_grad;
  const torch::Tensor obs = torch::from_blob(const_cast<float*>(observations.data()),
                                             {num_envs, obsDim()}, torch::kFloat);
  scaler_->toEnv(model_->actionMean(normalizer_->normalize(obs)), out);
}

}  // namespace ppo
}  // namespace jetbot_rl
