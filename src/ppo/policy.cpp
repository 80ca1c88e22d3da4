#include "jetbot_rl/ppo/policy.h"

#include <torch/torch.h>

#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {

Policy::Policy(const std::string& checkpoint) : meta_(readCheckpointMeta(checkpoint)) {
  const PpoConfig& c = meta_.config;
  model_ = ActorCritic(policyInputDim(c, meta_.obs_dim, meta_.action_dim), meta_.action_dim, c);
  normalizer_ = ObsNormalizer(meta_.obs_dim, c.normalize_observations);
  loadPolicy(checkpoint, model_, normalizer_);
  model_->eval();
  if (!meta_.spec.action_low.empty()) {
    setActionLimits(meta_.spec.action_low, meta_.spec.action_high);
  }
}

namespace {
std::string bounds(const std::vector<float>& low, const std::vector<float>& high) {
  std::ostringstream s;
  for (std::size_t i = 0; i < low.size(); ++i) {
    s << (i ? ", " : "") << "[" << low[i] << ", " << high[i] << "]";
  }
  return s.str();
}
}  // namespace

std::string Policy::setActionLimits(const std::vector<float>& low, const std::vector<float>& high) {
  if (static_cast<int>(low.size()) != actionDim()) {
    throw ConfigError("the env has " + std::to_string(low.size()) +
                      " action dimensions; the policy was trained for " +
                      std::to_string(actionDim()));
  }
  scaler_ = std::make_unique<ActionScaler>(low, high, meta_.config.action_squash);
  const BatchSpec& trained = meta_.spec;
  if (trained.action_low.empty() || (trained.action_low == low && trained.action_high == high)) {
    return "";
  }
  return "the env's action bounds " + bounds(low, high) + " differ from the checkpoint's " +
         bounds(trained.action_low, trained.action_high) +
         ": the policy's actions span the env's bounds";
}

void Policy::startMemory(int num_envs) {
  const PpoConfig& c = meta_.config;
  memory_envs_ = num_envs;
  fresh_ = torch::ones({num_envs}, torch::kBool);
  history_ = InputHistory::forConfig(c, num_envs, obsDim(), actionDim());
  if (model_->recurrent()) actor_state_ = model_->initialState(num_envs).actor;
}

void Policy::resetMemory(const std::vector<std::uint32_t>& envs) {
  if (!fresh_.defined()) return;  // nothing remembered yet
  bool* fresh = fresh_.data_ptr<bool>();
  for (std::uint32_t e : envs) {
    if (e >= static_cast<std::uint32_t>(memory_envs_)) {
      throw InputError("resetMemory: env " + std::to_string(e) + " of " +
                       std::to_string(memory_envs_));
    }
    fresh[e] = true;
  }
}

void Policy::resetMemory() {
  if (fresh_.defined()) fresh_.fill_(true);
}

void Policy::act(const std::vector<float>& observations, int num_envs, std::vector<float>& out) {
  if (!scaler_) throw Error("Policy::act before setActionLimits");
  if (num_envs < 1 || static_cast<std::int64_t>(observations.size()) !=
                          static_cast<std::int64_t>(num_envs) * obsDim()) {
    throw InputError("expected " + std::to_string(num_envs * obsDim()) + " observations, got " +
                     std::to_string(observations.size()));
  }
  torch::NoGradGuard no_grad;
  const torch::Tensor obs = torch::from_blob(const_cast<float*>(observations.data()),
                                             {num_envs, obsDim()}, torch::kFloat);
  if (!hasMemory()) {
    scaler_->toEnv(model_->actionMean(normalizer_->normalize(obs)), out);
    return;
  }
  if (num_envs != memory_envs_) startMemory(num_envs);
  // The same steps as Ppo::act: history pushed, recurrent state zeroed where an episode starts.
  const torch::Tensor input =
      history_
          ? history_->push(obs, fresh_,
                           [this](const torch::Tensor& o) { return normalizer_->normalize(o); })
          : normalizer_->normalize(obs);
  torch::Tensor mean;
  if (model_->recurrent()) {
    actor_state_ = startOver(actor_state_, fresh_);
    mean = model_->actionMean(input, &actor_state_);
  } else {
    mean = model_->actionMean(input);
  }
  if (history_) history_->pushActions(scaler_->squash(mean));
  fresh_.zero_();
  scaler_->toEnv(mean, out);
}

}  // namespace ppo
}  // namespace jetbot_rl
