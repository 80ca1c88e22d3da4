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

void toMsg(const StepResult& r, int num_envs, int obs_dim, const ros::Time& stamp, EnvStep& msg) {
  msg.header.stamp = stamp;
  msg.step = r.step;
  msg.num_envs = static_cast<std::uint32_t>(num_envs);
  msg.obs_dim = static_cast<std::uint32_t>(obs_dim);
  // assign() of contiguous ranges: one memcpy each, capacity kept between steps.
  msg.observations.assign(r.observations.begin(), r.observations.end());
  msg.rewards.assign(r.rewards.begin(), r.rewards.end());
  msg.terminated.assign(r.terminated.begin(), r.terminated.end());
  msg.truncated.assign(r.truncated.begin(), r.truncated.end());
  msg.episode_steps.assign(r.episode_steps.begin(), r.episode_steps.end());
  msg.reset_env_ids.assign(r.reset_env_ids.begin(), r.reset_env_ids.end());
  msg.final_observations.assign(r.final_observations.begin(), r.final_observations.end());
  msg.outcomes.assign(r.outcomes.begin(), r.outcomes.end());
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
  for (std::uint8_t o : msg.outcomes) {
    if (o > EnvStep::OUTCOME_WAITED) {
      throw Error("EnvStep " + std::to_string(msg.step) + ": outcomes holds " + std::to_string(o) +
                  ", not 0 to 5");
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
