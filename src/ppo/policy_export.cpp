// Policy::exportTorchScript: the trained policy as a self-contained TorchScript module, as Isaac
// Lab's exporter writes it (normaliser and action scaling inside).
#include <torch/csrc/jit/api/module.h>
#include <torch/nn/modules/linear.h>
#include <torch/torch.h>

#include <filesystem>
#include <sstream>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/policy.h"

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

std::string metaYaml(const BatchSpec& spec, const CheckpointMeta& meta) {
  std::ostringstream s;
  s << "# jetbot_rl policy: forward(obs [B, obs_dim] float32) -> actions [B, action_dim]\n"
    << "task: " << spec.task << "\nobs_dim: " << spec.obs_dim << "\naction_dim: " << spec.action_dim
    << "\nobservation_names: ";
  writeValue(s, spec.observation_names);
  s << "\naction_names: ";
  writeValue(s, spec.action_names);
  s << "\naction_low: ";
  writeValue(s, spec.action_low);
  s << "\naction_high: ";
  writeValue(s, spec.action_high);
  s << "\ncontrol_dt: " << spec.control_dt << "\niteration: " << meta.iteration
    << "\nenv_steps: " << meta.env_steps << "\n";
  return s.str();
}

}  // namespace

void Policy::exportTorchScript(const std::string& path, const BatchSpec& spec) const {
  if (!scaler_) throw Error("Policy::exportTorchScript before setActionLimits");
  torch::NoGradGuard no_grad;
  torch::jit::Module module("JetbotPolicy");
  std::ostringstream code;
  code << "def forward(self, obs: Tensor) -> Tensor:\n    x = obs\n";
  if (normalizer_->enabled()) {
    // The same float values and operations as ObsNormalizer::normalize.
    module.register_buffer("obs_mean", normalizer_->mean().to(torch::kFloat));
    module.register_buffer(
        "obs_std", (torch::sqrt(normalizer_->var()) + normalizer_->epsilon()).to(torch::kFloat));
    code << "    x = torch.clamp((x - self.obs_mean) / self.obs_std, " << -normalizer_->clip()
         << ", " << normalizer_->clip() << ")\n";
  }
  int layer = 0;
  for (const auto& child : model_->actor()->children()) {
    if (auto* linear = child->as<torch::nn::Linear>()) {
      const std::string k = std::to_string(layer++);
      module.register_buffer("weight_" + k, linear->weight.detach().clone());
      module.register_buffer("bias_" + k, linear->bias.detach().clone());
      // addmm is what torch::nn::Linear computes for a batch: the same sums, the same result.
      code << "    x = torch.addmm(self.bias_" << k << ", x, self.weight_" << k << ".t())\n";
    } else {
      code << "    x = " << activationCall(meta_.config.activation) << "\n";
    }
  }
  code << "    x = " << (scaler_->tanh() ? "torch.tanh(x)" : "torch.clamp(x, -1.0, 1.0)") << "\n";
  module.register_buffer("action_center", scaler_->center().clone());
  module.register_buffer("action_half_range", scaler_->halfRange().clone());
  code << "    return self.action_center + self.action_half_range * x\n";
  module.define(code.str());

  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  torch::jit::ExtraFilesMap extra{{"meta.yaml", metaYaml(spec, meta_)}};
  try {
    module.save(path, extra);
  } catch (const std::exception& e) {
    throw Error("cannot write the exported policy " + path + ": " + e.what());
  }
}

}  // namespace ppo
}  // namespace jetbot_rl
