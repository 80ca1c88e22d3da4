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

std::string metaYaml(const BatchSpec& spec, const CheckpointMeta& meta, int hidden_size,
                     const std::string& layout) {
  const PpoConfig& c = meta.config;
  std::ostringstream s;
  if (hidden_size == 0) {
    s << "# jetbot_rl policy: forward(obs [B, obs_dim] float32) -> actions [B, action_dim]\n";
  } else {
    s << "# jetbot_rl policy with memory: forward(obs [B, obs_dim] float32, hidden [B, "
         "hidden_size]) -> (actions [B, action_dim], hidden); initial_hidden(B) -> zeros, which "
         "start an env's memory over (at an episode or a command start)\n";
  }
  s << "task: " << spec.task << "\nobs_dim: " << spec.obs_dim << "\naction_dim: " << spec.action_dim
    << "\nobservation_names: ";
  writeValue(s, spec.observation_names);
  s << "\naction_names: ";
  writeValue(s, spec.action_names);
  s << "\naction_low: ";
  writeValue(s, spec.action_low);
  s << "\naction_high: ";
  writeValue(s, spec.action_high);
  s << "\nscan_beam_angles: ";
  writeValue(s, spec.scan_beam_angles);
  s << "\nscan_range: ";
  writeValue(s, spec.scan_range);
  s << "\ncontrol_dt: " << spec.control_dt << "\niteration: " << meta.iteration
    << "\nenv_steps: " << meta.env_steps << "\nmemory: " << (hidden_size > 0 ? "true" : "false")
    << "\nhidden_size: " << hidden_size << "\nhidden_layout: \"" << layout << "\""
    << "\nobs_history_length: " << c.obs_history_length
    << "\naction_history_length: " << c.action_history_length
    << "\nrnn_type: " << enumName(c.rnn_type) << "\nrnn_hidden_size: " << c.rnn_hidden_size
    << "\nrnn_num_layers: " << c.rnn_num_layers << "\n";
  return s.str();
}

/// "a:b" column slice of a 2-D tensor's columns.
std::string columns(int64_t from, int64_t to) {
  return "[:, " + std::to_string(from) + ":" + std::to_string(to) + "]";
}

}  // namespace

void Policy::exportTorchScript(const std::string& path, const BatchSpec& spec) const {
  if (!scaler_) throw Error("Policy::exportTorchScript before setActionLimits");
  torch::NoGradGuard no_grad;
  const PpoConfig& c = meta_.config;
  torch::jit::Module module("JetbotPolicy");
  std::ostringstream code;

  // normalize(x): the same float values and operations as ObsNormalizer::normalize.
  code << "def normalize(self, x: Tensor) -> Tensor:\n";
  if (normalizer_->enabled()) {
    module.register_buffer("obs_mean", normalizer_->mean().to(torch::kFloat));
    module.register_buffer(
        "obs_std", (torch::sqrt(normalizer_->var()) + normalizer_->epsilon()).to(torch::kFloat));
    code << "    return torch.clamp((x - self.obs_mean) / self.obs_std, " << -normalizer_->clip()
         << ", " << normalizer_->clip() << ")\n";
  } else {
    code << "    return x\n";
  }

  // The hidden row: [started flag, observation slots, action slots] with a history (as
  // InputHistory::push computes them), then the RNN's state (as RecurrentMemory::step).
  const bool history = hasHistory(c);
  const int64_t k = c.obs_history_length, o = obsDim(), m = c.action_history_length,
                a = actionDim();
  const int64_t obs_at = 1, actions_at = obs_at + k * o, rnn_at = history ? actions_at + m * a : 0;
  const RecurrentMemory& rnn = model_->actorMemory();
  const int64_t hidden_size = rnn_at + (rnn.is_empty() ? 0 : rnn->stateSize());
  std::string layout;
  if (history) {
    layout = "1 started flag (0: start over), " + std::to_string(k) + " x " + std::to_string(o) +
             " raw observations (newest first), " + std::to_string(m) + " x " + std::to_string(a) +
             " actions in [-1, 1] (newest first)";
  }
  if (!rnn.is_empty()) {
    layout += std::string(history ? ", " : "") + std::to_string(rnn->layers().size()) + " x " +
              (rnn->type() == RnnType::kLstm ? "(h, c)" : "h") + " of " +
              std::to_string(rnn->hiddenSize()) + " (" + enumName(rnn->type()) + ")";
  }

  std::vector<std::string> new_hidden;
  if (hidden_size == 0) {
    code << "def forward(self, obs: Tensor) -> Tensor:\n    x = self.normalize(obs)\n";
  } else {
    code << "def initial_hidden(self, batch: int) -> Tensor:\n"
         << "    return torch.zeros([batch, " << hidden_size << "])\n"
         << "def forward(self, obs: Tensor, hidden: Tensor) -> Tuple[Tensor, Tensor]:\n";
    if (history) {
      code << "    fresh = hidden" << columns(0, 1) << " == 0.0\n"
           << "    newest = obs.unsqueeze(1)\n"
           << "    slots = hidden" << columns(obs_at, actions_at) << ".reshape([-1, " << k << ", "
           << o << "])\n"
           << "    shifted = torch.cat([newest, slots[:, 0:" << k - 1 << "]], 1)\n"
           << "    slots = torch.where(fresh.unsqueeze(2), newest.expand_as(shifted), shifted)\n"
           << "    x = self.normalize(slots.reshape([-1, " << o << "])).reshape([-1, " << k * o
           << "])\n";
      new_hidden = {"torch.ones_like(hidden" + columns(0, 1) + ")",
                    "slots.reshape([-1, " + std::to_string(k * o) + "])"};
      if (m > 0) {
        code << "    acts = hidden" << columns(actions_at, rnn_at) << "\n"
             << "    acts = torch.where(fresh, torch.zeros_like(acts), acts)\n"
             << "    x = torch.cat([x, acts], 1)\n";
        new_hidden.push_back("a");
        new_hidden.push_back("acts" + columns(0, (m - 1) * a));
      }
    } else {
      code << "    x = self.normalize(obs)\n";
    }
    if (!rnn.is_empty()) {
      const int64_t h = rnn->hiddenSize();
      for (std::size_t l = 0; l < rnn->layers().size(); ++l) {
        const std::string n = std::to_string(l);
        const RecurrentMemoryImpl::Layer& w = rnn->layers()[l];
        for (const auto& [name, t] : {std::pair<std::string, torch::Tensor>{"w_ih_", w.w_ih},
                                      {"w_hh_", w.w_hh},
                                      {"b_ih_", w.b_ih},
                                      {"b_hh_", w.b_hh}}) {
          module.register_buffer(name + n, t.detach().clone());
        }
        const std::string weights =
            "self.w_ih_" + n + ", self.w_hh_" + n + ", self.b_ih_" + n + ", self.b_hh_" + n;
        if (rnn->type() == RnnType::kGru) {
          code << "    h" << n << " = torch.gru_cell(x, hidden"
               << columns(rnn_at + l * h, rnn_at + (l + 1) * h) << ", " << weights << ")\n";
          new_hidden.push_back("h" + n);
        } else {
          const int64_t at = rnn_at + 2 * l * h;
          code << "    h" << n << ", c" << n << " = torch.lstm_cell(x, [hidden"
               << columns(at, at + h) << ", hidden" << columns(at + h, at + 2 * h) << "], "
               << weights << ")\n";
          new_hidden.push_back("h" + n);
          new_hidden.push_back("c" + n);
        }
        code << "    x = h" << n << "\n";
      }
    }
  }
  int layer = 0;
  for (const auto& child : model_->actor()->children()) {
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
  code << "    a = " << (scaler_->tanh() ? "torch.tanh(x)" : "torch.clamp(x, -1.0, 1.0)") << "\n";
  module.register_buffer("action_center", scaler_->center().clone());
  module.register_buffer("action_half_range", scaler_->halfRange().clone());
  if (hidden_size == 0) {
    code << "    return self.action_center + self.action_half_range * a\n";
  } else {
    code << "    return self.action_center + self.action_half_range * a, torch.cat([";
    for (std::size_t i = 0; i < new_hidden.size(); ++i) code << (i ? ", " : "") << new_hidden[i];
    code << "], 1)\n";
  }
  try {
    module.define(code.str());
  } catch (const std::exception& e) {
    throw Error("cannot build the TorchScript policy: " + std::string(e.what()));
  }

  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  torch::jit::ExtraFilesMap extra{
      {"meta.yaml", metaYaml(spec, meta_, static_cast<int>(hidden_size), layout)}};
  try {
    module.save(path, extra);
  } catch (const std::exception& e) {
    throw Error("cannot write the exported policy " + path + ": " + e.what());
  }
}

}  // namespace ppo
}  // namespace jetbot_rl
