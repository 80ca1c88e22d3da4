// Policy::exportTorchScript: the trained policy as a self-contained TorchScript module, as Isaac
// Lab's exporter writes it (normaliser and action scaling inside).
#include <torch/csrc/jit/api/module.h>
#include <torch/nn/modules/conv.h>
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
  if (!spec.observer.camera_image.empty()) {
    s << "# jetbot_rl image policy: forward(obs [B, obs_dim] float32, image [B, camera_height, "
         "camera_width, 3] uint8 rgb8"
      << (memory.hidden_size == 0 ? "" : ", hidden [B, hidden_size]") << ") -> actions"
      << (memory.hidden_size == 0 ? "" : ", hidden") << "; the image's pre-processing inside\n";
  } else if (memory.hidden_size == 0) {
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

/// Lines of forward() that append the image encoder's features of `image` to `x`, as
/// ImageEncoder::forward computes them; its weights registered as buffers of `module`.
std::string imageScript(const ImageEncoderImpl& encoder, const MemoryScript& memory,
                        torch::jit::Module& module) {
  const ImageShape shape = encoder.shape();
  std::ostringstream code;
  if (shape.frames == 1) {
    code << "    p = image.reshape([-1, " << shape.height << ", " << shape.width
         << ", 3]).float().permute([0, 3, 1, 2]) * (1.0 / 255.0)\n";
    if (encoder.grayscale()) {
      module.register_buffer("luma", torch::tensor({0.299f, 0.587f, 0.114f}).view({1, 3, 1, 1}));
      code << "    p = (p * self.luma).sum(1, True)\n";
    }
  } else {  // the frame stack, as ImageFrames::push and ImageEncoder::forward make it
    const int64_t f = shape.frames, v = shape.frameValues(), at = memory.frames_at;
    code << "    newest = image.reshape([-1, 1, " << v << "]).float()\n"
         << "    fs = torch.cat([newest, hidden[:, " << at << ":" << at + (f - 1) * v
         << "].reshape([-1, " << f - 1 << ", " << v << "])], 1)\n"
         << "    fs = torch.where(fresh.unsqueeze(2), newest.expand_as(fs), fs)\n"
         << "    frames_kept = fs[:, 0:" << f - 1 << "].reshape([-1, " << (f - 1) * v << "])\n"
         << "    p = fs.reshape([-1, " << f << ", " << shape.height << ", " << shape.width
         << ", 3]).permute([0, 1, 4, 2, 3]) * (1.0 / 255.0)\n";
    if (encoder.grayscale()) {
      module.register_buffer("luma", torch::tensor({0.299f, 0.587f, 0.114f}).view({1, 1, 3, 1, 1}));
      code << "    p = (p * self.luma).sum(2)\n";
    } else {
      code << "    p = p.reshape([-1, " << f * 3 << ", " << shape.height << ", " << shape.width
           << "])\n";
    }
  }
  int layer = 0;
  for (const auto& child : encoder.convolutions()->children()) {
    auto* conv = child->as<torch::nn::Conv2d>();
    if (!conv) continue;  // the ReLUs, written with each convolution
    const std::string n = std::to_string(layer);
    const int stride = encoder.strides()[static_cast<std::size_t>(layer++)];
    module.register_buffer("conv_weight_" + n, conv->weight.detach().clone());
    module.register_buffer("conv_bias_" + n, conv->bias.detach().clone());
    code << "    p = torch.relu(torch.conv2d(p.contiguous(), self.conv_weight_" << n
         << ", self.conv_bias_" << n << ", [" << stride << ", " << stride << "]))\n";
  }
  module.register_buffer("image_weight", encoder.linear()->weight.detach().clone());
  module.register_buffer("image_bias", encoder.linear()->bias.detach().clone());
  code << "    p = torch.relu(torch.addmm(self.image_bias, p.flatten(1), self.image_weight.t()))\n"
       << "    x = torch.cat([x, p], 1)\n";
  return code.str();
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
  const std::string image_arg = observesImage() ? ", image: Tensor" : "";
  if (memory.hidden_size == 0) {
    code << "def forward(self, obs: Tensor" << image_arg << ") -> Tensor:\n";
  } else {
    code << "def initial_hidden(self, batch: int) -> Tensor:\n"
         << "    return torch.zeros([batch, " << memory.hidden_size << "])\n"
         << "def forward(self, obs: Tensor" << image_arg
         << ", hidden: Tensor) -> Tuple[Tensor, Tensor]:\n";
  }
  code << memory.code;
  if (observesImage()) code << imageScript(*model_->net->imageEncoder(), memory, module);
  code << memory.rnn_code;
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
