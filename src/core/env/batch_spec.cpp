#include <algorithm>
#include <sstream>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace {

template <typename T>
std::string text(const T& value) {
  std::ostringstream s;
  writeValue(s, value);
  return s.str();
}

}  // namespace

double topSpeed(const BatchSpec& spec) {
  if (actsByTwist(spec)) return spec.action_high.empty() ? 0.0 : spec.action_high[0];
  if (!(spec.observer.wheel_radius > 0.0) || spec.action_high.empty()) return 0.0;
  const double slowest = *std::min_element(spec.action_high.begin(), spec.action_high.end());
  return std::max(0.0, slowest * spec.observer.wheel_radius);
}

void checkFieldRules(const BatchSpec& s) {
  const auto need = [](bool ok, const char* field, const std::string& value,
                       const std::string& why) {
    if (!ok) throwInvalid(field, value, why);
  };
  need(s.num_envs >= 1, "num_envs", text(s.num_envs), "must be >= 1");
  need(s.obs_dim >= 1, "obs_dim", text(s.obs_dim), "must be >= 1");
  need(s.action_dim >= 1, "action_dim", text(s.action_dim), "must be >= 1");
  const auto sized = [&](const char* field, std::size_t size, int expected, const char* of) {
    need(size == static_cast<std::size_t>(expected), field, std::to_string(size) + " values",
         "must hold " + std::to_string(expected) + " (" + of + ")");
  };
  sized("action_low", s.action_low.size(), s.action_dim, "action_dim");
  sized("action_high", s.action_high.size(), s.action_dim, "action_dim");
  sized("action_names", s.action_names.size(), s.action_dim, "action_dim");
  sized("observation_names", s.observation_names.size(), s.obs_dim, "obs_dim");
  sized("observation_low", s.observation_low.size(), s.obs_dim, "obs_dim");
  sized("observation_high", s.observation_high.size(), s.obs_dim, "obs_dim");
  need(s.max_episode_length >= 2, "max_episode_length", text(s.max_episode_length), "must be >= 2");
  need(s.control_dt > 0.0, "control_dt", text(s.control_dt), "must be > 0");
  const std::vector<std::string> kinds{"rgb", "depth", "label"};
  std::size_t next = 0;  // each kind once, in that order
  for (const std::string& kind : s.image_kinds) {
    const auto at = std::find(kinds.begin(), kinds.end(), kind);
    need(at != kinds.end() && static_cast<std::size_t>(at - kinds.begin()) >= next, "image_kinds",
         kind, "must be among rgb, depth, label, each once and in that order");
    next = static_cast<std::size_t>(at - kinds.begin()) + 1;
  }
  const int low = s.image_kinds.empty() ? 0 : 1, high = s.image_kinds.empty() ? 0 : 4096;
  const std::string range =
      s.image_kinds.empty() ? "must be 0 without image_kinds" : "must be in [1, 4096] px";
  need(s.image_width >= low && s.image_width <= high, "image_width", text(s.image_width), range);
  need(s.image_height >= low && s.image_height <= high, "image_height", text(s.image_height),
       range);
  checkFieldRules(s.observer);
  if (!s.observer.camera_image.empty()) {  // the policy's image is the batch's
    const bool carried = carriesImage(s, s.observer.camera_image) &&
                         s.image_width == s.observer.camera_width &&
                         s.image_height == s.observer.camera_height;
    need(carried, "camera_image", s.observer.camera_image,
         "must be among image_kinds at image_width x image_height (" + text(s.image_width) + " x " +
             text(s.image_height) + ") when the policy observes it");
  }
}

std::unique_ptr<TaskObserver> makeObserver(const BatchSpec& spec) {
  return makeObserver(spec.task, spec.action_dim, spec.observer);
}

std::vector<std::string> specDifferences(const BatchSpec& mine, const BatchSpec& theirs,
                                         bool policy_bound_only, bool skip_unset) {
  std::vector<std::string> mine_text, theirs_text, names, unset;
  const auto collect = [](std::vector<std::string>& out, std::vector<std::string>* field_names) {
    return [&out, field_names](const char* name, const auto& value, const auto&, const char*) {
      out.push_back(text(value));
      if (field_names) field_names->push_back(name);
    };
  };
  const BatchSpec defaults;
  if (policy_bound_only) {
    visitPolicyBoundFields(mine, collect(mine_text, &names));
    visitPolicyBoundFields(theirs, collect(theirs_text, nullptr));
    visitPolicyBoundFields(defaults, collect(unset, nullptr));
  } else {
    visitFields(mine, collect(mine_text, &names));
    visitFields(theirs, collect(theirs_text, nullptr));
    visitFields(defaults, collect(unset, nullptr));
  }
  std::vector<std::string> differences;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == "num_envs" || mine_text[i] == theirs_text[i]) continue;
    if (skip_unset && mine_text[i] == unset[i]) continue;
    differences.push_back(names[i] + ": " + theirs_text[i] + " differs from " + mine_text[i]);
  }
  return differences;
}

}  // namespace jetbot_rl
