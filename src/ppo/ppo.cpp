#include "jetbot_rl/ppo/ppo.h"

#include <torch/nn/utils/clip_grad.h>

#include <algorithm>
#include <string>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/ppo_losses.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

namespace {

torch::Tensor floats(const std::vector<float>& v, int rows, int cols) {
  return torch::from_blob(const_cast<float*>(v.data()), {rows, cols}, torch::kFloat).clone();
}

torch::Tensor flags(const std::vector<std::uint8_t>& v) {
  return torch::from_blob(const_cast<std::uint8_t*>(v.data()), {static_cast<int64_t>(v.size())},
                          torch::kUInt8)
      .to(torch::kFloat);
}

}  // namespace

Ppo::Ppo(const BatchSpec& spec, const PpoConfig& config)
    : config_(config),
      num_envs_(spec.num_envs),
      obs_dim_(spec.obs_dim),
      input_dim_(policyInputDim(config, spec.obs_dim, spec.action_dim)),
      image_(imageShapeOf(spec)),
      model_(input_dim_, spec.action_dim, config, image_),
      normalizer_(spec.obs_dim, config.normalize_observations),
      storage_(config.num_steps_per_env, spec.num_envs, input_dim_, spec.action_dim,
               model_->imageValues()),
      scaler_(spec.action_low, spec.action_high, config.action_squash),
      learning_rate_(config.learning_rate) {
  optimizer_ = std::make_unique<torch::optim::Adam>(model_->parameters(),
                                                    torch::optim::AdamOptions(learning_rate_));
  if (model_->recurrent() && config.num_mini_batches > spec.num_envs) {
    throwInvalid("num_mini_batches", config.num_mini_batches,
                 "must be <= num_envs = " + std::to_string(spec.num_envs) +
                     " with an RNN (a minibatch holds whole env sequences)");
  }
  memory_ = std::make_unique<PolicyMemory>(config, model_, spec.num_envs, spec.obs_dim,
                                           spec.action_dim, /*with_critic=*/true);
}

void Ppo::setLearningRate(double lr) {
  learning_rate_ = lr;
  for (auto& group : optimizer_->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);
  }
}

double Ppo::actionStd() { return model_->actionStd().mean().item<double>(); }

torch::Tensor Ppo::peekValues(const torch::Tensor& rows, const torch::Tensor& obs,
                              const torch::Tensor& fresh, const torch::Tensor& images) {
  torch::NoGradGuard no_grad;
  const torch::Tensor input = memory_->peekInput(
      rows, obs, fresh, [this](const torch::Tensor& o) { return normalize(o); }, images);
  if (!model_->recurrent()) return model_->value(input);
  const torch::Tensor critic = memory_->peekCriticState(rows, fresh);
  return model_->value(input, &critic);
}

const std::vector<float>& Ppo::act(const StepResult& state) {
  if (step_ >= storage_.numSteps()) {
    throw Error("Ppo::act: the rollout holds " + std::to_string(step_) +
                " steps already; call update() first");
  }
  if (state.observations.size() != static_cast<std::size_t>(num_envs_) * obs_dim_) {
    throw Error("Ppo::act: expected " + std::to_string(num_envs_ * obs_dim_) +
                " observations, got " + std::to_string(state.observations.size()));
  }
  const torch::Tensor obs = floats(state.observations, num_envs_, obs_dim_);
  normalizer_->update(obs);
  // The rollout keeps the recurrent states before step 0 and where episodes start, so that the
  // update recomputes every step's state (RecurrentMemory::sequence) as acting did here.
  if (model_->recurrent() && step_ == 0) storage_.setInitialState(memory_->state());
  obs_ = memory_->begin(
      obs, [this](const torch::Tensor& o) { return normalize(o); },
      image_.empty() ? torch::Tensor()
                     : imageInput(state.images.rgb, num_envs_, image_, "images_rgb"));
  if (model_->recurrent()) storage_.addStarts(step_, memory_->starts());
  sample_ = model_->act(obs_, &memory_->state());
  memory_->end(scaler_.squash(sample_.actions));
  scaler_.toEnv(sample_.actions, actions_);
  acted_ = true;
  return actions_;
}

void Ppo::processEnvStep(const StepResult& r) {
  if (!acted_) throw Error("Ppo::processEnvStep without act()");
  const int n = num_envs_;
  if (r.rewards.size() != static_cast<std::size_t>(n) || r.terminated.size() != r.rewards.size() ||
      r.truncated.size() != r.rewards.size() ||
      r.final_observations.size() != r.reset_env_ids.size() * obs_dim_) {
    throw Error("step " + std::to_string(r.step) + " does not match the batch (" +
                std::to_string(n) + " envs, obs_dim " + std::to_string(obs_dim_) + ")");
  }
  // Time-outs bootstrap with V(final observation), never as terminal states.
  std::vector<std::uint8_t> has_final(n, 0);
  std::vector<int64_t> rows, envs;
  for (std::size_t k = 0; k < r.reset_env_ids.size(); ++k) {
    const std::uint32_t id = r.reset_env_ids[k];
    if (id >= static_cast<std::uint32_t>(n)) {
      throw Error("step " + std::to_string(r.step) + ": reset env id " + std::to_string(id) +
                  " is out of range");
    }
    has_final[id] = 1;
    if (r.truncated[id] && !r.terminated[id]) {
      rows.push_back(static_cast<int64_t>(k));
      envs.push_back(id);
    }
  }
  for (int i = 0; i < n; ++i) {
    if ((r.truncated[i] || r.terminated[i]) && !has_final[i]) {
      throw Error("env " + std::to_string(i) + " ended in step " + std::to_string(r.step) +
                  " but has no final observation in reset_env_ids");
    }
  }
  // V(final observation) continues the env's history and recurrent state.
  torch::Tensor truncated_values = torch::zeros({n});
  if (!rows.empty()) {
    const int ended = static_cast<int>(r.reset_env_ids.size());
    std::vector<int64_t> ended_ids(r.reset_env_ids.begin(), r.reset_env_ids.end());
    const torch::Tensor v =
        peekValues(
            torch::tensor(ended_ids, torch::kLong), floats(r.final_observations, ended, obs_dim_),
            torch::zeros({ended}, torch::kBool),
            image_.empty() ? torch::Tensor()
                           : imageInput(r.final_images.rgb, ended, image_, "final_images_rgb"))
            .index_select(0, torch::tensor(rows, torch::kLong));
    truncated_values.index_copy_(0, torch::tensor(envs, torch::kLong), v);
  }
  const torch::Tensor rewards =
      torch::from_blob(const_cast<float*>(r.rewards.data()), {n}, torch::kFloat).clone();
  storage_.add(step_, obs_, sample_.actions, sample_.log_probs, sample_.values, sample_.mean,
               sample_.std, rewards, flags(r.terminated), flags(r.truncated), truncated_values);
  memory_->reset(r.reset_env_ids);
  ++step_;
  acted_ = false;
}

void Ppo::computeReturns(const StepResult& state) {
  if (step_ != storage_.numSteps()) {
    throw Error("Ppo::computeReturns: the rollout holds " + std::to_string(step_) + " of " +
                std::to_string(storage_.numSteps()) + " steps");
  }
  const torch::Tensor last_values =
      peekValues(torch::arange(num_envs_, torch::kLong),
                 floats(state.observations, num_envs_, obs_dim_), memory_->fresh(),
                 image_.empty() ? torch::Tensor()
                                : imageInput(state.images.rgb, num_envs_, image_, "images_rgb"));
  storage_.computeReturns(last_values, config_.gamma, config_.lam);
}

UpdateStats Ppo::update() {
  const RolloutStorage& storage = storage_;
  const PpoConfig& c = config_;
  UpdateStats stats;
  int updates = 0;
  const auto params = model_->parameters();
  if (learning_rate_ > lr_ceiling_) setLearningRate(lr_ceiling_);
  for (int epoch = 0; epoch < c.num_learning_epochs; ++epoch) {
    const std::vector<MiniBatch> batches = model_->recurrent()
                                               ? storage.sequenceMiniBatches(c.num_mini_batches)
                                               : storage.miniBatches(c.num_mini_batches);
    for (const MiniBatch& b : batches) {
      const ActionEvaluation e = model_->recurrent()
                                     ? model_->evaluateSequence(b.obs, b.actions, b.state, b.starts)
                                     : model_->evaluate(b.obs, b.actions);

      // KL(old || new) drives the adaptive learning rate (rsl_rl).
      const double kl = gaussianKl(b.old_mean, b.old_std, e.mean, e.std);
      setLearningRate(std::min(adaptedLearningRate(learning_rate_, kl, c), lr_ceiling_));

      const torch::Tensor ratio = torch::exp(e.log_probs - b.old_log_probs);
      const torch::Tensor surrogate = clippedSurrogate(ratio, b.advantages, c.clip_param);
      const torch::Tensor value_loss =
          valueLoss(e.values, b.old_values, b.returns, c.clip_param, c.use_clipped_value_loss);
      const torch::Tensor entropy = e.entropy.mean();
      const torch::Tensor loss =
          surrogate + c.value_loss_coef * value_loss - c.entropy_coef * entropy;

      optimizer_->zero_grad();
      loss.backward();
      torch::nn::utils::clip_grad_norm_(params, c.max_grad_norm);
      optimizer_->step();

      stats.value_loss += value_loss.item<double>();
      stats.surrogate_loss += surrogate.item<double>();
      stats.entropy += entropy.item<double>();
      stats.approx_kl += kl;
      ++updates;
    }
  }
  stats.value_loss /= updates;
  stats.surrogate_loss /= updates;
  stats.entropy /= updates;
  stats.approx_kl /= updates;
  stats.learning_rate = learning_rate_;
  step_ = 0;
  return stats;
}

}  // namespace ppo
}  // namespace jetbot_rl
