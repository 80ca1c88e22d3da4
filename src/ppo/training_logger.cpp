#include "jetbot_rl/ppo/training_logger.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

}  // namespace

std::string describeSummary(const TrainingSummary& s) {
  std::ostringstream o;
  o << "status: "
    << (!s.error.empty() ? "failed: " + s.error
        : s.interrupted  ? "interrupted"
                         : "completed")
    << "\niterations: " << s.iterations << "\nenv_steps: " << s.env_steps
    << "\nelapsed_s: " << fixed(s.elapsed_s, 1)
    << "\nfinal_mean_reward_per_step: " << fixed(s.final_reward, 4)
    << "\nfinal_mean_episode_return: "
    << (std::isnan(s.final_episode_return) ? std::string("nan") : fixed(s.final_episode_return, 2))
    << (s.best_by == BestBy::kEpisodeReturn ? "\nbest_mean_episode_return: "
        : s.best_by == BestBy::kLast        ? "\nlast_mean_reward_per_step: "
                                            : "\nbest_mean_reward_per_step: ")
    << fixed(s.best_reward, 4) << "\nmean_env_steps_per_s: " << fixed(s.mean_env_steps_per_s, 0)
    << "\ntarget_mean_reward_per_step: " << fixed(s.target_reward, 4);
  if (s.target_iteration >= 0) {
    o << "\ntarget_reached_at_iteration: " << s.target_iteration
      << "\ntarget_reached_at_env_steps: " << s.target_env_steps
      << "\ntarget_reached_at_elapsed_s: " << fixed(s.target_elapsed_s, 1);
  } else {
    o << "\ntarget_reached_at_iteration: never";
  }
  o << "\nrun_dir: " << s.run_dir;
  return o.str();
}

TrainingLogger::TrainingLogger(int num_envs, const LoggerOptions& options, TrainingSummary& summary)
    : options_(options),
      summary_(summary),
      csv_(options.csv_path, options.keep_rows, options.obs_names),
      tracker_(num_envs),
      sink_([](const std::string& line) { std::cout << line << std::endl; }),
      obs_sum_(options.obs_names.size(), 0.0) {
  summary_.target_reward = options.target_reward;
  summary_.best_by = options.best_by;
  summary_.final_episode_return = std::nan("");
}

void TrainingLogger::startedAt(const std::vector<std::uint32_t>& episode_steps) {
  for (std::size_t i = 0; i < episode_steps.size(); ++i) {
    if (episode_steps[i] > 0) tracker_.skipCurrent(static_cast<std::uint32_t>(i));
  }
}

void TrainingLogger::recordObservations(const StepResult& state) {
  const std::size_t obs_dim = obs_sum_.size();
  for (std::size_t i = 0; i < state.episode_steps.size(); ++i) {
    if (state.episode_steps[i] < static_cast<std::uint32_t>(options_.obs_stats_from_step)) {
      continue;
    }
    for (std::size_t k = 0; k < obs_dim; ++k) obs_sum_[k] += state.observations[i * obs_dim + k];
    ++obs_count_;
  }
}

void TrainingLogger::recordStep(const StepResult& result) {
  for (float r : result.rewards) reward_sum_ += r;
  reward_count_ += static_cast<std::int64_t>(result.rewards.size());
  for (std::uint8_t o : result.outcomes) {
    const int rate = outcomeRate(o);  // a round's wait counts in none
    if (rate >= 0) ++outcomes_[rate];
  }
  tracker_.add(result);
}

bool TrainingLogger::endIteration(IterationStats& s) {
  s.mean_reward_per_step = reward_count_ > 0 ? reward_sum_ / reward_count_ : 0.0;
  s.mean_episode_return = tracker_.meanReturn();
  s.episodes = tracker_.episodes();
  const double ended = static_cast<double>(outcomes_[0] + outcomes_[1] + outcomes_[2]);
  const double none = std::nan("");
  s.timeout_rate = ended > 0 ? outcomes_[0] / ended : none;
  s.success_rate = ended > 0 ? outcomes_[1] / ended : none;
  s.collision_rate = ended > 0 ? outcomes_[2] / ended : none;
  std::fill(std::begin(outcomes_), std::end(outcomes_), 0);
  s.obs_names = options_.obs_names;
  s.obs_samples = obs_count_;
  s.obs_means.clear();
  for (double sum : obs_sum_) {
    s.obs_means.push_back(obs_count_ > 0 ? sum / static_cast<double>(obs_count_) : std::nan(""));
  }
  reward_sum_ = 0.0;
  reward_count_ = 0;
  std::fill(obs_sum_.begin(), obs_sum_.end(), 0.0);
  obs_count_ = 0;

  csv_.append(s);
  log(progressLine(s));
  if (s.mean_reward_per_step >= options_.target_reward && summary_.target_iteration < 0) {
    summary_.target_iteration = s.iteration;
    summary_.target_env_steps = s.env_steps;
    summary_.target_elapsed_s = s.elapsed_s;
  }
  summary_.iterations = s.iteration;
  summary_.env_steps = s.env_steps;
  summary_.final_reward = s.mean_reward_per_step;
  summary_.final_episode_return = s.mean_episode_return;
  // A mean return is NaN before the first episode ends: no comparison makes it the best.
  const double value =
      options_.best_by == BestBy::kEpisodeReturn ? s.mean_episode_return : s.mean_reward_per_step;
  const bool best = options_.best_by == BestBy::kLast || value > summary_.best_reward;
  if (best) summary_.best_reward = value;
  return best;
}

}  // namespace ppo
}  // namespace jetbot_rl
