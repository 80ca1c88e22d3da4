#include "jetbot_rl/eval/observation_means.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jetbot_rl {

void ObservationMeans::beforeStep(const BatchedEnv& env) {
  if (from_step_ < 0) return;
  const int obs_dim = env.obsDim();
  sum_.resize(obs_dim, 0.0);
  abs_sum_.resize(obs_dim, 0.0);
  const StepResult& now = env.state();
  for (int e = 0; e < env.numEnvs(); ++e) {
    if (now.episode_steps[e] < static_cast<std::uint32_t>(from_step_)) continue;
    for (int k = 0; k < obs_dim; ++k) {
      const double x = now.observations[static_cast<std::size_t>(e) * obs_dim + k];
      sum_[k] += x;
      abs_sum_[k] += std::abs(x);
    }
    ++samples_;
  }
}

void ObservationMeans::print(const std::vector<std::string>& names) const {
  std::printf("obs_samples=%lld\n", static_cast<long long>(samples_));
  const double n = static_cast<double>(std::max<std::int64_t>(samples_, 1));
  for (std::size_t k = 0; k < names.size(); ++k) {
    const double sum = k < sum_.size() ? sum_[k] : 0.0;
    const double abs_sum = k < abs_sum_.size() ? abs_sum_[k] : 0.0;
    std::printf("obs_mean_%s=%.4f\nobs_mean_abs_%s=%.4f\n", names[k].c_str(), sum / n,
                names[k].c_str(), abs_sum / n);
  }
}

}  // namespace jetbot_rl
