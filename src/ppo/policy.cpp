#include "jetbot_rl/ppo/policy.h"

#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/checkpoint.h"
#include "jetbot_rl/ppo/policy_model.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

Policy::Policy(const std::string& checkpoint)
    : meta_(readCheckpointMeta(checkpoint)), model_(std::make_unique<Model>()) {
  const NetworkConfig& c = meta_.config;
  model_->net = ActorCritic(policyInputDim(c, meta_.obs_dim, meta_.action_dim), meta_.action_dim, c,
                            imageShapeOf(meta_.spec));
  model_->normalizer = ObsNormalizer(meta_.obs_dim, c.normalize_observations);
  loadPolicy(checkpoint, model_->net, model_->normalizer);
  model_->net->eval();
  if (!meta_.spec.action_low.empty()) {
    setActionLimits(meta_.spec.action_low, meta_.spec.action_high);
  }
}

Policy::~Policy() = default;
Policy::Policy(Policy&&) noexcept = default;
Policy& Policy::operator=(Policy&&) noexcept = default;

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
  model_->scaler = std::make_unique<ActionScaler>(low, high, meta_.config.action_squash);
  const BatchSpec& trained = meta_.spec;
  if (trained.action_low.empty() || (trained.action_low == low && trained.action_high == high)) {
    return "";
  }
  return "the env's action bounds " + bounds(low, high) + " differ from the checkpoint's " +
         bounds(trained.action_low, trained.action_high) +
         ": the policy's actions span the env's bounds";
}

std::vector<std::string> Policy::fitTo(const BatchSpec& env) {
  const BatchSpec& trained = meta_.spec;
  const std::vector<std::string> bound = specDifferences(trained, env, true, true);
  if (!bound.empty()) {
    throw ConfigError("the env does not fit the policy: the env's " + bound.front() +
                      ", the checkpoint's (a policy observes and acts as it was trained)");
  }
  std::vector<std::string> warnings;
  const std::string bounds_changed = setActionLimits(env.action_low, env.action_high);
  if (!bounds_changed.empty()) warnings.push_back(bounds_changed);
  for (const std::string& d : specDifferences(trained, env, false, true)) {
    if (d.rfind("action_low", 0) == 0 || d.rfind("action_high", 0) == 0) continue;  // just said
    warnings.push_back("the env's " + d + ", the checkpoint's");
  }
  return warnings;
}

void Policy::resetMemory(const std::vector<std::uint32_t>& envs) {
  if (model_->memory)
    model_->memory->reset(envs);  // before the first act() every env starts anyway
}

void Policy::resetMemory() {
  if (model_->memory) model_->memory->resetAll();
}

void Policy::act(const std::vector<float>& observations, int num_envs, std::vector<float>& out) {
  if (observesImage()) {
    throw InputError("the policy observes " + std::to_string(imageWidth()) + " x " +
                     std::to_string(imageHeight()) +
                     " rgb camera images: act(observations, images, ...) takes them");
  }
  act(observations, {}, num_envs, out);
}

void Policy::act(const std::vector<float>& observations, const std::vector<std::uint8_t>& images,
                 int num_envs, std::vector<float>& out) {
  if (!model_->scaler) throw Error("Policy::act before setActionLimits");
  if (num_envs < 1 || static_cast<std::int64_t>(observations.size()) !=
                          static_cast<std::int64_t>(num_envs) * obsDim()) {
    throw InputError("expected " + std::to_string(num_envs * obsDim()) + " observations, got " +
                     std::to_string(observations.size()));
  }
  // Checked before anything changes: a wrong number of image bytes steps no memory.
  const torch::Tensor pixels =
      observesImage() ? imageInput(images, num_envs, imageShapeOf(meta_.spec), "images")
                      : torch::Tensor();
  torch::NoGradGuard no_grad;
  const torch::Tensor obs = torch::from_blob(const_cast<float*>(observations.data()),
                                             {num_envs, obsDim()}, torch::kFloat);
  std::unique_ptr<PolicyMemory>& memory = model_->memory;
  if (!memory || memory->numEnvs() != num_envs) {
    memory = std::make_unique<PolicyMemory>(meta_.config, model_->net, num_envs, obsDim(),
                                            actionDim(), /*with_critic=*/false);
  }
  const ObsNormalizer& normalizer = model_->normalizer;
  const torch::Tensor input = memory->begin(
      obs, [&normalizer](const torch::Tensor& o) { return normalizer->normalize(o); }, pixels);
  const torch::Tensor mean =
      model_->net->actionMean(input, memory->recurrent() ? &memory->state().actor : nullptr);
  memory->end(model_->scaler->squash(mean));
  model_->scaler->toEnv(mean, out);
}

void setTorchThreads(int threads) { torch::set_num_threads(threads); }

}  // namespace ppo
}  // namespace jetbot_rl
