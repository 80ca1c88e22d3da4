#include "jetbot_rl/ppo/actor_critic.h"

#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/linear.h>

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

torch::nn::Sequential makeMlp(int in, const std::vector<int>& hidden, int out,
                              Activation activation) {
  torch::nn::Sequential mlp;
  int width = in;
  for (int h : hidden) {
    mlp->push_back(torch::nn::Linear(width, h));
    switch (activation) {
      case Activation::kElu:
        mlp->push_back(torch::nn::ELU());
        break;
      case Activation::kTanh:
        mlp->push_back(torch::nn::Tanh());
        break;
      case Activation::kRelu:
        mlp->push_back(torch::nn::ReLU());
        break;
    }
    width = h;
  }
  mlp->push_back(torch::nn::Linear(width, out));
  return mlp;
}

const double kHalfLog2Pi = 0.5 * std::log(2.0 * M_PI);

torch::Tensor gaussianLogProb(const torch::Tensor& x, const torch::Tensor& mean,
                              const torch::Tensor& log_std) {
  const torch::Tensor z = (x - mean) * torch::exp(-log_std);
  return (-0.5 * z * z - log_std - kHalfLog2Pi).sum(-1);
}

}  // namespace

ActorCriticImpl::ActorCriticImpl(int input_dim, int action_dim,
                                 const std::vector<int>& actor_hidden_dims,
                                 const std::vector<int>& critic_hidden_dims, Activation activation,
                                 double init_noise_std)
    : ActorCriticImpl(input_dim, action_dim, [&] {
        NetworkConfig c;
        c.actor_hidden_dims = actor_hidden_dims;
        c.critic_hidden_dims = critic_hidden_dims;
        c.activation = activation;
        c.init_noise_std = init_noise_std;
        return c;
      }()) {}

ActorCriticImpl::ActorCriticImpl(int input_dim, int action_dim, const NetworkConfig& c,
                                 ImageShape image)
    : input_dim_(input_dim), action_dim_(action_dim) {
  if (input_dim < 1 || action_dim < 1) {
    throw ConfigError("invalid model size: input " + std::to_string(input_dim) + ", action_dim " +
                      std::to_string(action_dim));
  }
  int features = input_dim;
  if (image.empty() && c.image_frames > 1) {
    throwInvalid("image_frames", c.image_frames,
                 "stacks camera images: the env's observation contract names no camera_image");
  }
  if (!image.empty()) {
    encoder_ = register_module("image_encoder", ImageEncoder(c, image));
    features += encoder_->features();
  }
  if (c.rnn_type != RnnType::kNone) {
    // The RNNs remember what the MLPs would see: the input and the image's features.
    actor_rnn_ = register_module(
        "actor_rnn", RecurrentMemory(c.rnn_type, features, c.rnn_hidden_size, c.rnn_num_layers));
    critic_rnn_ = register_module(
        "critic_rnn", RecurrentMemory(c.rnn_type, features, c.rnn_hidden_size, c.rnn_num_layers));
    features = c.rnn_hidden_size;
  }
  actor_ =
      register_module("actor", makeMlp(features, c.actor_hidden_dims, action_dim, c.activation));
  critic_ = register_module("critic", makeMlp(features, c.critic_hidden_dims, 1, c.activation));
  log_std_ = register_parameter(
      "log_std", torch::full({action_dim}, std::log(c.init_noise_std), torch::kFloat));
}

torch::Tensor ActorCriticImpl::features(const torch::Tensor& input) {
  if (encoder_.is_empty()) return input;
  // The encoder takes rows of pixels: [B, values] or a sequence's [T, B, values].
  std::vector<int64_t> sizes = input.sizes().vec();
  sizes.back() = encoder_->features();
  return torch::cat({input.narrow(-1, 0, input_dim_),
                     encoder_->forward(input.narrow(-1, input_dim_, imageValues())).view(sizes)},
                    -1);
}

MemoryState ActorCriticImpl::initialState(int64_t batch) const {
  MemoryState s;
  if (recurrent()) {
    s.actor = torch::zeros({batch, actor_rnn_->stateSize()});
    s.critic = torch::zeros({batch, critic_rnn_->stateSize()});
  }
  return s;
}

ActionSample ActorCriticImpl::act(const torch::Tensor& input, MemoryState* state) {
  torch::NoGradGuard no_grad;
  ActionSample s;
  const torch::Tensor x = features(input);
  s.mean = meanOf(x, state ? &state->actor : nullptr);
  s.std = torch::exp(log_std_).expand_as(s.mean);
  s.actions = s.mean + s.std * torch::randn_like(s.mean);
  s.log_probs = gaussianLogProb(s.actions, s.mean, log_std_);
  if (recurrent()) {
    s.values = critic_->forward(critic_rnn_->step(x, state->critic)).squeeze(-1);
  } else {
    s.values = critic_->forward(x).squeeze(-1);
  }
  return s;
}

ActionEvaluation ActorCriticImpl::evaluate(const torch::Tensor& input,
                                           const torch::Tensor& actions) {
  if (recurrent()) throw Error("ActorCritic::evaluate of a recurrent model: use evaluateSequence");
  ActionEvaluation e;
  const torch::Tensor x = features(input);
  e.mean = actor_->forward(x);
  e.std = torch::exp(log_std_).expand_as(e.mean);
  e.log_probs = gaussianLogProb(actions, e.mean, log_std_);
  e.entropy = (0.5 + kHalfLog2Pi + log_std_).sum().expand({input.size(0)});
  e.values = critic_->forward(x).squeeze(-1);
  return e;
}

ActionEvaluation ActorCriticImpl::evaluateSequence(const torch::Tensor& input,
                                                   const torch::Tensor& actions,
                                                   const MemoryState& state,
                                                   const torch::Tensor& starts) {
  if (!recurrent()) throw Error("ActorCritic::evaluateSequence of a model without an RNN");
  const torch::Tensor x = features(input);
  const torch::Tensor actor_features = actor_rnn_->sequence(x, state.actor, starts);
  const torch::Tensor critic_features = critic_rnn_->sequence(x, state.critic, starts);
  ActionEvaluation e;
  e.mean = actor_->forward(actor_features.flatten(0, 1));
  e.std = torch::exp(log_std_).expand_as(e.mean);
  e.log_probs = gaussianLogProb(actions.flatten(0, 1), e.mean, log_std_);
  e.entropy = (0.5 + kHalfLog2Pi + log_std_).sum().expand({e.mean.size(0)});
  e.values = critic_->forward(critic_features.flatten(0, 1)).squeeze(-1);
  return e;
}

torch::Tensor ActorCriticImpl::actionMean(const torch::Tensor& input, torch::Tensor* actor_state) {
  return meanOf(features(input), actor_state);
}

torch::Tensor ActorCriticImpl::meanOf(const torch::Tensor& x, torch::Tensor* actor_state) {
  if (!recurrent()) return actor_->forward(x);
  if (!actor_state) throw Error("ActorCritic::actionMean of a recurrent model without a state");
  return actor_->forward(actor_rnn_->step(x, *actor_state));
}

torch::Tensor ActorCriticImpl::value(const torch::Tensor& input,
                                     const torch::Tensor* critic_state) {
  const torch::Tensor x = features(input);
  if (!recurrent()) return critic_->forward(x).squeeze(-1);
  if (!critic_state) throw Error("ActorCritic::value of a recurrent model without a state");
  torch::Tensor state = *critic_state;  // step() replaces its copy, not the caller's
  return critic_->forward(critic_rnn_->step(x, state)).squeeze(-1);
}

torch::Tensor ActorCriticImpl::actionStd() const { return torch::exp(log_std_).detach(); }

}  // namespace ppo
}  // namespace jetbot_rl
