#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/ppo/update_stats.h"

namespace jetbot_rl {
namespace ppo {

/// The figures of one training iteration: a progress line, a CSV row, a ~training_stats message.
struct IterationStats {
  std::int64_t iteration = 0;         ///< Completed iterations, 1-based.
  std::int64_t iterations = 0;        ///< Iterations the run is to complete.
  std::int64_t env_steps = 0;         ///< Env steps so far (control steps x envs).
  double mean_reward_per_step = 0.0;  ///< Mean reward over this iteration's rollout [m/s].
  double mean_episode_return = 0.0;   ///< Mean return of the last 100 episodes; NaN before one.
  double env_steps_per_s = 0.0;       ///< This iteration's env steps / its wall time.
  double elapsed_s = 0.0;             ///< Wall time of training so far [s].
  double time_left_s = 0.0;           ///< Estimate for the remaining iterations [s].
  double collection_s = 0.0;          ///< Wall time of this iteration's rollout [s].
  double update_s = 0.0;              ///< Wall time of this iteration's PPO update [s].
  UpdateStats update;                 ///< Losses, entropy, KL, learning rate.
  double action_std = 0.0;            ///< Mean policy std [normalised action units].
  std::int64_t episodes = 0;          ///< Episodes completed so far.
  /// Of the episodes that ended in this iteration: the fractions that reached the task's goal,
  /// ended badly (a collision) and timed out (StepResult::outcomes); NaN when none ended.
  double success_rate = 0.0, collision_rate = 0.0, timeout_rate = 0.0;
  /// Names of the observation components (BatchSpec::observation_names): obs_mean_<name> columns.
  std::vector<std::string> obs_names;
  /// Per observation component: mean over the rollout's late samples (see RunnerOptions::
  /// obs_stats_from_step) [the component's unit]; NaN when the rollout had none.
  std::vector<double> obs_means;
  std::int64_t obs_samples = 0;  ///< Late samples (env steps) behind obs_means.
};

/// Names of the CSV columns / ~training_stats entries, in order; starts with the required
/// iteration,env_steps,mean_reward_per_step,mean_episode_return,env_steps_per_s,elapsed_s,
/// then collection_s ... episodes, success_rate, collision_rate, timeout_rate; ends with
/// obs_samples and one obs_mean_<name> per entry of `obs_names`.
std::vector<std::string> statsColumns(const std::vector<std::string>& obs_names = {});
/// The values of statsColumns(s.obs_names), in order.
std::vector<double> statsValues(const IterationStats& s);
/// statsColumns(obs_names) joined by commas.
std::string csvHeader(const std::vector<std::string>& obs_names = {});
/// One CSV row (no newline); NaN as "nan".
std::string csvRow(const IterationStats& s);
/// The line printed per iteration: iteration, env steps, mean reward per step, mean episode
/// return, env steps/s, elapsed and time left.
std::string progressLine(const IterationStats& s);

}  // namespace ppo
}  // namespace jetbot_rl
