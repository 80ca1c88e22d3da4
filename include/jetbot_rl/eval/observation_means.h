#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/eval/episode_loop.h"

namespace jetbot_rl {

/// The mean and mean absolute value of each observation a policy acted on at episode step
/// `from_step` or later (jetbot_rl_evaluate --obs-from-step; < 0: none counted).
class ObservationMeans : public EpisodeObserver {
 public:
  explicit ObservationMeans(int from_step) : from_step_(from_step) {}
  void beforeStep(const BatchedEnv& env) override;
  /// Prints obs_samples= and, per observation `names[k]`, obs_mean_<name>= and
  /// obs_mean_abs_<name>= lines on stdout.
  void print(const std::vector<std::string>& names) const;

 private:
  int from_step_;
  std::vector<double> sum_, abs_sum_;
  std::int64_t samples_ = 0;
};

}  // namespace jetbot_rl
