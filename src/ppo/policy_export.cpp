// Policy::exportTorchScript: the trained policy as a self-contained TorchScript module, as Isaac
// Lab's exporter writes it (normaliser and action scaling inside).
#include <torch/csrc/jit/api/module.h>
#include <torch/nn/modules/linear.h>

#include <filesystem>
#include <sstream>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/policy_memory.h"
#include "jetbot_rl/ppo/policy_model.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string activationCall(Activation a) {
  switch (a) {
    case Activation::kTanh:
      return "torch.tanh(x)";
    case Activation::kRelu:
      return "torch.relu(x)";
    case Activation::kElu:
      break;
  }
  return "torch.elu(x)";
}

std::string metaYaml(const BatchSpec& spec, const CheckpointMeta& meta,
                     const MemoryScript& memory) {
  std::ostringstream s;
  if (memory.hidden_size == 0) {
    s << "# jetbot_rl policy: forward(obs [B, obs_dim] float32) -> actions [B, action_dim]\n";
  } else {
    s << "# jetbot_rl policy with memory: forward(obs [B, obs_dim] float32, hidden [B, "
         "hidden_size]) -> (actions [B, action_dim], hidden); initial_hidden(B) -> zeros, which "
         "start an env's memory over (at an episode or a command start)\n";
  }
  // The env's spec and the network by their field lists; then what the export adds.
  s << fieldsToYaml(spec) << "iteration: " << meta.iteration << "\nenv_steps: " << meta.env_steps
    << "\nmemory: " << (memory.hidden_size > 0 ? "true" : "false")
    << "\nhidden_size: " << memory.hidden_size << "\nhidden_layout: \"" << memory.layout << "\"\n"
    << networkYaml(meta.config);
  return s.str();
}

}  // namespace

void Policy::exportTorchScript(const std::string& path, const BatchSpec& spec) const {
  if (!model_->scaler) throw Error("Policy::exportTorchScript before setActionLimits");
  const ObsNormalizer& normalizer = model_->normalizer;
  const ActionScaler& scaler = *model_->scaler;
  torch::NoGradGuard no_grad;
  const NetworkConfig& c = meta_.config;
  torch::jit::Module module("JetbotPolicy");
  std::ostringstream code;

  // normalize(x): the same float values and operations as ObsNormalizer::normalize.
  code << "def normalize(self, x: Tensor) -> Tensor:\n";
  if (normalizer->enabled()) {
    module.register_buffer("obs_mean", normalizer->mean().to(torch::kFloat));
    module.register_buffer(
        "obs_std", (torch::sqrt(normalizer->var()) + normalizer->epsilon()).to(torch::kFloat));
    code << "    return torch.clamp((x - self.obs_mean) / self.obs_std, " << -normalizer->clip()
         << ", " << normalizer->clip() << ")\n";
  } else {
    code << "    return x\n";
  }

  const MemoryScript memory = memoryScript(c, model_->net, obsDim(), actionDim(), module);
  if (memory.hidden_size == 0) {
    code << "def forward(self, obs: Tensor) -> Tensor:\n";
  } else {
    code << "def initial_hidden(self, batch: int) -> Tensor:\n"
         << "    return torch.zeros([batch, " << memory.hidden_size << "])\n"
         << "def forward(self, obs: Tensor, hidden: Tensor) -> Tuple[Tensor, Tensor]:\n";
  }
  code << memory.code;
  int layer = 0;
  for (const auto& child : model_->net->actor()->children()) {
    if (auto* linear = child->as<torch::nn::Linear>()) {
      const std::string n = std::to_string(layer++);
      module.register_buffer("weight_" + n, linear->weight.detach().clone());
      module.register_buffer("bias_" + n, linear->bias.detach().clone());
      // addmm is what torch::nn::Linear computes for a batch: the same sums, the same result.
      code << "    x = torch.addmm(self.bias_" << n << ", x, self.weight_" << n << ".t())\n";
    } else {
      code << "    x = " << activationCall(c.activation) << "\n";
    }
  }
  code << "    a = " << (scaler.tanh() ? "torch.tanh(x)" : "torch.clamp(x, -1.0, 1.0)") << "\n";
  module.register_buffer("action_center", scaler.center().clone());
  module.register_buffer("action_half_range", scaler.halfRange().clone());
  if (memory.hidden_size == 0) {
    code << "    return self.action_center + self.action_half_range * a\n";
  } else {
    code << "    return self.action_center + self.action_half_range * a, torch.cat([";
    for (std::size_t i = 0; i < memory.new_hidden.size(); ++i) {
      code << (i ? ", " : "") << memory.new_hidden[i];
    }
    code << "], 1)\n";
  }
  try {
    module.define(code.str());
  } catch (const std::exception& e) {
    throw Error("cannot build the TorchScript policy: " + std::string(e.what()));
  }

  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  torch::jit::ExtraFilesMap extra{{"meta.yaml", metaYaml(spec, meta_, memory)}};
  try {
    module.save(path, extra);
  } catch (const std::exception& e) {
    throw Error("cannot write the exported policy " + path + ": " + e.what());
  }
}

}  // namespace ppo
}  // namespace jetbot_rl
