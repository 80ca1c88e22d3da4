#include "jetbot_rl/ros/common/msg_conversion.h"

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/msg_fields.h"

namespace jetbot_rl {
namespace {

void checkSize(const char* field, std::size_t size, std::size_t expected, std::uint64_t step) {
  if (size != expected) {
    throw Error("EnvStep " + std::to_string(step) + ": " + field + " has " + std::to_string(size) +
                " values, expected " + std::to_string(expected));
  }
}

}  // namespace

/// The values one image of `kind` holds in a batch of `spec`; 0 for a kind it does not carry.
std::size_t imageValues(const BatchSpec& spec, const char* kind) {
  if (!carriesImage(spec, kind)) return 0;
  const auto pixels = static_cast<std::size_t>(spec.image_width) * spec.image_height;
  return std::string(kind) == "rgb" ? 3 * pixels : pixels;
}

/// `to` = `from` when the batch carries images of `kind`, else empty.
template <typename To, typename From>
void assignImages(const BatchSpec& spec, const char* kind, To& to, const From& from) {
  if (carriesImage(spec, kind)) {
    to.assign(from.begin(), from.end());
  } else {
    to.clear();
  }
}

void toMsg(const StepResult& r, const BatchSpec& spec, const ros::Time& stamp, EnvStep& msg) {
  msg.header.stamp = stamp;
  msg.step = r.step;
  msg.num_envs = static_cast<std::uint32_t>(spec.num_envs);
  msg.obs_dim = static_cast<std::uint32_t>(spec.obs_dim);
  // assign() of contiguous ranges: one memcpy each, capacity kept between steps.
  msg.observations.assign(r.observations.begin(), r.observations.end());
  msg.rewards.assign(r.rewards.begin(), r.rewards.end());
  msg.terminated.assign(r.terminated.begin(), r.terminated.end());
  msg.truncated.assign(r.truncated.begin(), r.truncated.end());
  msg.episode_steps.assign(r.episode_steps.begin(), r.episode_steps.end());
  msg.reset_env_ids.assign(r.reset_env_ids.begin(), r.reset_env_ids.end());
  msg.final_observations.assign(r.final_observations.begin(), r.final_observations.end());
  msg.outcomes.assign(r.outcomes.begin(), r.outcomes.end());
  assignImages(spec, "rgb", msg.images_rgb, r.images.rgb);
  assignImages(spec, "depth", msg.images_depth, r.images.depth);
  assignImages(spec, "label", msg.images_label, r.images.label);
  if (spec.image_kinds.empty()) {
    msg.images_fresh.clear();
  } else {
    msg.images_fresh.assign(r.images.fresh.begin(), r.images.fresh.end());
  }
  assignImages(spec, "rgb", msg.final_images_rgb, r.final_images.rgb);
  assignImages(spec, "depth", msg.final_images_depth, r.final_images.depth);
  assignImages(spec, "label", msg.final_images_label, r.final_images.label);
}

void fromMsg(const EnvStep& msg, const BatchSpec& spec, StepResult& r) {
  const auto n = static_cast<std::size_t>(spec.num_envs);
  const auto obs_dim = static_cast<std::size_t>(spec.obs_dim);
  checkSize("num_envs", msg.num_envs, n, msg.step);
  checkSize("obs_dim", msg.obs_dim, obs_dim, msg.step);
  checkSize("observations", msg.observations.size(), n * obs_dim, msg.step);
  checkSize("rewards", msg.rewards.size(), n, msg.step);
  checkSize("terminated", msg.terminated.size(), n, msg.step);
  checkSize("truncated", msg.truncated.size(), n, msg.step);
  checkSize("episode_steps", msg.episode_steps.size(), n, msg.step);
  checkSize("final_observations", msg.final_observations.size(), msg.reset_env_ids.size() * obs_dim,
            msg.step);
  checkSize("outcomes", msg.outcomes.size(), msg.reset_env_ids.size(), msg.step);
  const std::size_t ended = msg.reset_env_ids.size();
  const std::size_t rgb = imageValues(spec, "rgb"), depth = imageValues(spec, "depth"),
                    label = imageValues(spec, "label");
  checkSize("images_rgb", msg.images_rgb.size(), n * rgb, msg.step);
  checkSize("images_depth", msg.images_depth.size(), n * depth, msg.step);
  checkSize("images_label", msg.images_label.size(), n * label, msg.step);
  checkSize("images_fresh", msg.images_fresh.size(), spec.image_kinds.empty() ? 0 : n, msg.step);
  checkSize("final_images_rgb", msg.final_images_rgb.size(), ended * rgb, msg.step);
  checkSize("final_images_depth", msg.final_images_depth.size(), ended * depth, msg.step);
  checkSize("final_images_label", msg.final_images_label.size(), ended * label, msg.step);
  for (std::uint8_t o : msg.outcomes) {
    if (o > EnvStep::OUTCOME_OFF_TRACK) {
      throw Error("EnvStep " + std::to_string(msg.step) + ": outcomes holds " + std::to_string(o) +
                  ", not 0 to 6");
    }
  }
  for (std::uint32_t id : msg.reset_env_ids) {
    if (id >= n) {
      throw Error("EnvStep " + std::to_string(msg.step) + ": reset_env_ids holds " +
                  std::to_string(id) + ", out of range [0, " + std::to_string(n) + ")");
    }
  }
  r.step = msg.step;
  r.observations.assign(msg.observations.begin(), msg.observations.end());
  r.rewards.assign(msg.rewards.begin(), msg.rewards.end());
  r.terminated.assign(msg.terminated.begin(), msg.terminated.end());
  r.truncated.assign(msg.truncated.begin(), msg.truncated.end());
  r.episode_steps.assign(msg.episode_steps.begin(), msg.episode_steps.end());
  r.reset_env_ids.assign(msg.reset_env_ids.begin(), msg.reset_env_ids.end());
  r.final_observations.assign(msg.final_observations.begin(), msg.final_observations.end());
  r.outcomes.assign(msg.outcomes.begin(), msg.outcomes.end());
  r.divergences.clear();
  r.images.width = r.final_images.width = spec.image_width;
  r.images.height = r.final_images.height = spec.image_height;
  r.images.rgb.assign(msg.images_rgb.begin(), msg.images_rgb.end());
  r.images.depth.assign(msg.images_depth.begin(), msg.images_depth.end());
  r.images.label.assign(msg.images_label.begin(), msg.images_label.end());
  r.images.fresh.assign(msg.images_fresh.begin(), msg.images_fresh.end());
  r.final_images.rgb.assign(msg.final_images_rgb.begin(), msg.final_images_rgb.end());
  r.final_images.depth.assign(msg.final_images_depth.begin(), msg.final_images_depth.end());
  r.final_images.label.assign(msg.final_images_label.begin(), msg.final_images_label.end());
}

EnvSpec toMsg(const BatchSpec& spec) {
  EnvSpec msg;
  // Field by field, by name: BatchSpec's field list and the message's definition.
  visitFields(spec, [&msg](const char* name, const auto& value, const auto&, const char*) {
    bool found = false;
    visitMsgFields(msg, [&](const std::string& field, auto& to) {
      if (field != name) return;
      assignField(field, to, value);
      found = true;
    });
    if (!found) throw Error(std::string("EnvSpec.msg has no field ") + name + " (BatchSpec has)");
  });
  return msg;
}

BatchSpec fromMsg(const EnvSpec& msg) {
  BatchSpec spec;
  visitMsgFields(msg, [&spec](const std::string& field, const auto& from) {
    visitFields(spec, [&](const char* name, auto& to, const auto&, const char*) {
      if (field == name) assignField(field, to, from);
    });
  });
  try {
    validateConfig(spec);
  } catch (const ConfigError& e) {
    throw Error(std::string("inconsistent EnvSpec: ") + e.what());
  }
  return spec;
}

}  // namespace jetbot_rl
