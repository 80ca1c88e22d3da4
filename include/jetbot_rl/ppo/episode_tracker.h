#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "jetbot_rl/env/step_result.h"

namespace jetbot_rl {
namespace ppo {

/// Accumulates per-env episode returns and keeps the last `window` completed ones.
class EpisodeTracker {
 public:
  explicit EpisodeTracker(int num_envs, std::size_t window = 100);

  /// Adds one step's rewards; returns the returns of the episodes that ended in it (in
  /// reset_env_ids order).
  const std::vector<double>& add(const StepResult& batch);
  /// The running episode of env `id` is not counted when it ends (it started part-way).
  void skipCurrent(std::uint32_t id);
  /// Mean return of the last `window` completed episodes; NaN before the first one ends.
  double meanReturn() const;
  /// Episodes completed so far.
  std::int64_t episodes() const { return episodes_; }

 private:
  std::vector<double> current_, ended_;
  std::vector<std::uint8_t> skip_;  // per env: do not count the running episode
  std::deque<double> recent_;
  std::size_t window_;
  std::int64_t episodes_ = 0;
};

}  // namespace ppo
}  // namespace jetbot_rl
