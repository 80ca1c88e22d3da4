// memoryScript(): PolicyMemory's steps as TorchScript, for the exported policy (policy_export.cpp).
#include <torch/csrc/jit/api/module.h>

#include "jetbot_rl/ppo/policy_memory.h"
#include "jetbot_rl/ppo/recurrent_memory.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// "a:b" column slice of a 2-D tensor's columns.
std::string columns(int64_t from, int64_t to) {
  return "[:, " + std::to_string(from) + ":" + std::to_string(to) + "]";
}

}  // namespace

MemoryScript memoryScript(const NetworkConfig& c, const ActorCritic& model, int obs_dim,
                          int action_dim, torch::jit::Module& module) {
  MemoryScript script;
  // The hidden row: [started flag, observation slots, action slots] with a history (as
  // InputHistory::push computes them), the frame stack's earlier images (as ImageFrames::push;
  // after the flag), then the RNN's state (as RecurrentMemory::step).
  const bool history = hasHistory(c);
  const bool frames = c.image_frames > 1 && model->imageValues() > 0;
  const int64_t k = c.obs_history_length, o = obs_dim, m = c.action_history_length, a = action_dim;
  const int64_t f = c.image_frames, v = frames ? model->imageValues() / f : 0;
  const int64_t obs_at = 1, actions_at = obs_at + k * o;
  const int64_t frames_at = history ? actions_at + m * a : frames ? 1 : 0;
  const int64_t rnn_at = frames_at + (frames ? (f - 1) * v : 0);
  const RecurrentMemory& rnn = model->actorMemory();
  script.hidden_size = rnn_at + (rnn.is_empty() ? 0 : rnn->stateSize());
  if (history) {
    script.layout = "1 started flag (0: start over), " + std::to_string(k) + " x " +
                    std::to_string(o) + " raw observations (newest first), " + std::to_string(m) +
                    " x " + std::to_string(a) + " actions in [-1, 1] (newest first)";
  }
  if (frames) {
    script.layout += std::string(history ? ", " : "1 started flag (0: start over), ") +
                     std::to_string(f - 1) + " x " + std::to_string(v) +
                     " image bytes (the frame stack's earlier images, newest first)";
    script.frames_at = frames_at;
  }
  if (!rnn.is_empty()) {
    script.layout += std::string(history || frames ? ", " : "") +
                     std::to_string(rnn->layers().size()) + " x " +
                     (rnn->type() == RnnType::kLstm ? "(h, c)" : "h") + " of " +
                     std::to_string(rnn->hiddenSize()) + " (" + enumName(rnn->type()) + ")";
  }
  if (script.hidden_size == 0) {
    script.code = "    x = self.normalize(obs)\n";
    return script;
  }
  std::ostringstream code;
  if (history) {
    code << "    fresh = hidden" << columns(0, 1) << " == 0.0\n"
         << "    newest = obs.unsqueeze(1)\n"
         << "    slots = hidden" << columns(obs_at, actions_at) << ".reshape([-1, " << k << ", "
         << o << "])\n"
         << "    shifted = torch.cat([newest, slots[:, 0:" << k - 1 << "]], 1)\n"
         << "    slots = torch.where(fresh.unsqueeze(2), newest.expand_as(shifted), shifted)\n"
         << "    x = self.normalize(slots.reshape([-1, " << o << "])).reshape([-1, " << k * o
         << "])\n";
    script.new_hidden = {"torch.ones_like(hidden" + columns(0, 1) + ")",
                         "slots.reshape([-1, " + std::to_string(k * o) + "])"};
    if (m > 0) {
      code << "    acts = hidden" << columns(actions_at, rnn_at) << "\n"
           << "    acts = torch.where(fresh, torch.zeros_like(acts), acts)\n"
           << "    x = torch.cat([x, acts], 1)\n";
      script.new_hidden.push_back("a");  // the action of this step, once the MLP gave it
      script.new_hidden.push_back("acts" + columns(0, (m - 1) * a));
    }
  } else if (frames) {
    code << "    fresh = hidden" << columns(0, 1) << " == 0.0\n"
         << "    x = self.normalize(obs)\n";
    script.new_hidden = {"torch.ones_like(hidden" + columns(0, 1) + ")"};
  } else {
    code << "    x = self.normalize(obs)\n";
  }
  if (frames) script.new_hidden.push_back("frames_kept");  // imageScript() makes them
  script.code = code.str();
  if (!rnn.is_empty()) {
    std::ostringstream rnn_code;  // after the image's features join x (policy_export.cpp)
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
        rnn_code << "    h" << n << " = torch.gru_cell(x, hidden"
                 << columns(rnn_at + l * h, rnn_at + (l + 1) * h) << ", " << weights << ")\n";
        script.new_hidden.push_back("h" + n);
      } else {
        const int64_t at = rnn_at + 2 * l * h;
        rnn_code << "    h" << n << ", c" << n << " = torch.lstm_cell(x, [hidden"
                 << columns(at, at + h) << ", hidden" << columns(at + h, at + 2 * h) << "], "
                 << weights << ")\n";
        script.new_hidden.push_back("h" + n);
        script.new_hidden.push_back("c" + n);
      }
      rnn_code << "    x = h" << n << "\n";
    }
    script.rnn_code = rnn_code.str();
  }
  return script;
}

}  // namespace ppo
}  // namespace jetbot_rl
