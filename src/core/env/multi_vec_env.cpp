#include "jetbot_rl/env/multi_vec_env.h"

namespace jetbot_rl {
namespace {

/// ConfigError unless `b` (part `name`) agrees with `a` (part `first`) on everything but num_envs.
void checkAgrees(const BatchSpec& a, const std::string& first, const BatchSpec& b,
                 const std::string& name) {
  const std::vector<std::string> differences = specDifferences(a, b, false, false);
  if (differences.empty()) return;
  std::string text;
  for (const std::string& d : differences) text += (text.empty() ? "" : "; ") + d;
  throw ConfigError("env " + name + " differs from env " + first + ": " + text +
                    " (every env of a batch must agree on all but num_envs)");
}

}  // namespace

MultiVecEnv::MultiVecEnv(std::vector<std::unique_ptr<VecEnv>> parts, std::vector<std::string> names)
    : parts_(std::move(parts)), names_(std::move(names)) {
  if (parts_.empty()) throw ConfigError("MultiVecEnv: no envs given");
  if (names_.size() != parts_.size()) throw ConfigError("MultiVecEnv: one name per env needed");
  spec_ = parts_[0]->spec();
  spec_.num_envs = 0;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    checkAgrees(parts_[0]->spec(), names_[0], parts_[k]->spec(), names_[k]);
    offsets_.push_back(spec_.num_envs);
    spec_.num_envs += parts_[k]->spec().num_envs;
  }
  slices_.resize(parts_.size());
  answers_.resize(parts_.size());
}

std::int64_t MultiVecEnv::partSeed(std::int64_t seed, std::size_t k) {
  return seed < 0 ? seed : seed + static_cast<std::int64_t>(k) * kSeedStride;
}

const StepResult& MultiVecEnv::reset(std::int64_t seed,
                                     const std::vector<std::uint32_t>& episode_steps) {
  if (!episode_steps.empty() && episode_steps.size() != static_cast<std::size_t>(spec_.num_envs)) {
    throw InputError("episode_steps: expected " + std::to_string(spec_.num_envs) +
                     " values or none, got " + std::to_string(episode_steps.size()));
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    std::vector<std::uint32_t> starts;
    if (!episode_steps.empty()) {
      const auto first = episode_steps.begin() + offsets_[k];
      starts.assign(first, first + parts_[k]->spec().num_envs);
    }
    answers_[k] = &parts_[k]->reset(partSeed(seed, k), starts);
  }
  return gather(answers_);
}

void MultiVecEnv::stepAsync(const std::vector<float>& actions) {
  const std::size_t a = static_cast<std::size_t>(spec_.action_dim);
  if (actions.size() != static_cast<std::size_t>(spec_.num_envs) * a) {
    throw InputError("actions: expected " + std::to_string(spec_.num_envs * spec_.action_dim) +
                     " values, got " + std::to_string(actions.size()));
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const auto first = actions.begin() + static_cast<std::ptrdiff_t>(offsets_[k] * a);
    slices_[k].assign(first, first + static_cast<std::ptrdiff_t>(parts_[k]->spec().num_envs * a));
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) parts_[k]->stepAsync(slices_[k]);
}

const StepResult& MultiVecEnv::stepWait() {
  for (std::size_t k = 0; k < parts_.size(); ++k) answers_[k] = &parts_[k]->stepWait();
  return gather(answers_);
}

const StepResult& MultiVecEnv::gather(const std::vector<const StepResult*>& results) {
  StepResult& r = result_;
  r.step = results[0]->step;
  r.observations.clear();
  r.rewards.clear();
  r.terminated.clear();
  r.truncated.clear();
  r.episode_steps.clear();
  r.reset_env_ids.clear();
  r.final_observations.clear();
  r.outcomes.clear();
  r.divergences.clear();
  clearImages(r.images);
  clearImages(r.final_images);
  r.images.width = r.final_images.width = spec_.image_width;
  r.images.height = r.final_images.height = spec_.image_height;
  const auto append = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  const auto appendImages = [&append](BatchImages& to, const BatchImages& from) {
    append(to.rgb, from.rgb);
    append(to.depth, from.depth);
    append(to.label, from.label);
    append(to.fresh, from.fresh);
  };
  for (std::size_t k = 0; k < results.size(); ++k) {
    const StepResult& p = *results[k];
    const auto offset = static_cast<std::uint32_t>(offsets_[k]);
    append(r.observations, p.observations);
    append(r.rewards, p.rewards);
    append(r.terminated, p.terminated);
    append(r.truncated, p.truncated);
    append(r.episode_steps, p.episode_steps);
    for (std::uint32_t id : p.reset_env_ids) r.reset_env_ids.push_back(id + offset);
    append(r.final_observations, p.final_observations);
    append(r.outcomes, p.outcomes);
    appendImages(r.images, p.images);
    appendImages(r.final_images, p.final_images);
    for (const Divergence& d : p.divergences) {
      r.divergences.push_back({d.env + offset, names_[k] + ": " + d.reason});
    }
  }
  return r;
}

}  // namespace jetbot_rl
