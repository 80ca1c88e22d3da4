#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/env/vec_env.h"

namespace jetbot_rl {

/**
 * Several VecEnvs (env nodes on one or several hosts) as one batch, in list order: part k's envs
 * follow part k-1's. A step sends every part its slice of the actions first, then waits for
 * every answer, so the parts step concurrently. Part k is reset with seed `partSeed(seed, k)`,
 * so a run is reproducible for a given list of parts.
 */
class MultiVecEnv : public VecEnv {
 public:
  /// Takes the parts and their names (for messages). Throws ConfigError naming the part and the
  /// field when a part's spec disagrees with the first's (everything but num_envs must agree).
  MultiVecEnv(std::vector<std::unique_ptr<VecEnv>> parts, std::vector<std::string> names);

  /// Seeds of consecutive parts lie this far apart (Reset.srv's NODE_SEED_STRIDE, which the ROS
  /// client checks against it at compile time): every env of the batch has a stream of its own.
  static constexpr std::int64_t kSeedStride = std::int64_t{1} << 32;
  /// The seed part `k` is reset with: `seed` + k x kSeedStride (part 0 keeps `seed`); < 0 stays
  /// < 0.
  static std::int64_t partSeed(std::int64_t seed, std::size_t k);

  const BatchSpec& spec() const override { return spec_; }
  /// Resets every part; `episode_steps` (empty or num_envs values) is split in list order.
  const StepResult& reset(std::int64_t seed,
                          const std::vector<std::uint32_t>& episode_steps = {}) override;
  /// Sends every part its slice (InputError for a wrong size, before anything is sent).
  void stepAsync(const std::vector<float>& actions) override;
  /// Waits for every part's answer and concatenates them; `step` is the first part's.
  const StepResult& stepWait() override;

  std::size_t numParts() const { return parts_.size(); }
  /// First env of part `k` in the batch.
  int offset(std::size_t k) const { return offsets_.at(k); }

 private:
  /// Concatenates the parts' results into result_.
  const StepResult& gather(const std::vector<const StepResult*>& results);

  std::vector<std::unique_ptr<VecEnv>> parts_;
  std::vector<std::string> names_;
  std::vector<int> offsets_;
  BatchSpec spec_;
  StepResult result_;
  std::vector<std::vector<float>> slices_;  // actions per part, reused
  std::vector<const StepResult*> answers_;
};

}  // namespace jetbot_rl
