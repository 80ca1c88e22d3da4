#include "jetbot_rl/ppo/actor_critic.h"

#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/linear.h>
#include <torch/torch.h>

#include <cmath>

#include "jetbot_rl/errors.h"

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

ActorCriticImpl::ActorCriticImpl(int obs_dim, int action_dim,
                                 const std::vector<int>& actor_hidden_dims,
                                 const std::vector<int>& critic_hidden_dims, Activation activation,
                                 double init_noise_std)
    : obs_dim_(obs_dim), action_dim_(action_dim) {
  if (obs_dim < 1 || action_dim < 1) {
    throw ConfigError("invalid model size: obs_dim " + std::to_string(obs_dim) + ", action_dim " +
                      std::to_string(action_dim));
  }
  actor_ = register_module("actor", makeMlp(obs_dim, actor_hidden_dims, action_dim, activation));
  critic_ = register_module("critic", makeMlp(obs_dim, critic_hidden_dims, 1, activation));
  log_std_ = register_parameter("log_std",
                                torch::full({action_dim}, std::log(init_noise_std), torch::kFloat));
}

ActionSample ActorCriticImpl::act(const torch::Tensor& obs) {
  torch::NoGradGuard no_grad;
  ActionSample s;
  s.mean = actor_->forward(obs);
  s.std = torch::exp(log_std_).expand_as(s.mean);
  s.actions = s.mean + s.std * torch::randn_like(s.mean);
  s.log_probs = gaussianLogProb(s.actions, s.mean, log_std_);
  s.values = critic_->forward(obs).squeeze(-1);
  return s;
}

ActionEvaluation ActorCriticImpl::evaluate(const torch::Tensor& obs, const torch::Tensor& actions) {
  ActionEvaluation e;
  e.mean = actor_->forward(obs);
  e.std = torch::exp(log_std_).expand_as(e.mean);
  e.log_probs = gaussianLogProb(actions, e.mean, log_std_);
  e.entropy = (0.5 + kHalfLog2Pi + log_std_).sum().expand({obs.size(0)});
  e.values = critic_->forward(obs).squeeze(-1);
  return e;
}

torch::Tensor ActorCriticImpl::actionMean(const torch::Tensor& obs) { return actor_->forward(obs); }

torch::Tensor ActorCriticImpl::value(const torch::Tensor& obs) {
  return critic_->forward(obs).squeeze(-1);
}

torch::Tensor ActorCriticImpl::actionStd() const { return torch::exp(log_std_).detach(); }

}  // namespace ppo
}  // namespace jetbot_rl
