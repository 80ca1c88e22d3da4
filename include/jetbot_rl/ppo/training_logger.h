#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/episode_tracker.h"
#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/progress_csv.h"
#include "jetbot_rl/ppo/runner_options.h"

namespace jetbot_rl {
namespace ppo {

/// The final figures of a run.
struct TrainingSummary {
  bool interrupted = false;     ///< Stopped early (Ctrl-C); checkpoints/latest.pt was saved.
  std::string error;            ///< Non-empty: the run failed (e.g. the env stopped answering).
  std::int64_t iterations = 0;  ///< Completed iterations.
  std::int64_t env_steps = 0;
  double elapsed_s = 0.0;
  double final_reward = 0.0;                ///< Mean reward per step of the last iteration [m/s].
  double final_episode_return = 0.0;        ///< Mean return of the last 100 episodes.
  BestBy best_by = BestBy::kRewardPerStep;  ///< What best_reward measures.
  double best_reward = -1e300;  ///< Best iteration's mean reward per step (or episode return).
  double target_reward = 0.0;
  std::int64_t target_iteration = -1;  ///< First iteration reaching target_reward; -1: never.
  std::int64_t target_env_steps = -1;
  double target_elapsed_s = -1.0;
  double mean_env_steps_per_s = 0.0;  ///< Env steps / wall time of this session.
  std::string run_dir;
};

/// The final figures as "name: value" lines (printed at the end and written to summary.yaml).
std::string describeSummary(const TrainingSummary& summary);

/// How the logger reports a run.
struct LoggerOptions {
  std::string csv_path;         ///< progress.csv
  std::int64_t keep_rows = -1;  ///< Resumed run: keep the CSV rows up to this iteration.
  double target_reward = 0.54;  ///< First iteration with mean reward/step >= this is noted.
  BestBy best_by = BestBy::kRewardPerStep;  ///< What makes an iteration the best so far.
  int obs_stats_from_step = 0;  ///< obs_mean_* columns: samples at this episode step or later.
  std::vector<std::string> obs_names;  ///< One per observation component (obs_mean_<name>).
};

/**
 * The training run's figures, apart from the learning (rsl_rl's logger): episode returns,
 * reward per step, the observation means late in episodes, the progress line, progress.csv, the
 * per-iteration callback and the final summary.
 */
class TrainingLogger {
 public:
  /// Opens the CSV (Error when it cannot be written).
  TrainingLogger(int num_envs, const LoggerOptions& options, TrainingSummary& summary);

  /// Where progress lines and notes go (default: stdout).
  void setSink(std::function<void(const std::string&)> sink) { sink_ = std::move(sink); }
  void log(const std::string& line) const { sink_(line); }

  /// Envs that start their first episode part-way (staggered starts, `episode_steps` > 0): that
  /// short episode's return is not counted.
  void startedAt(const std::vector<std::uint32_t>& episode_steps);
  /// The state the policy acts on next: its late-episode observations are averaged.
  void recordObservations(const StepResult& state);
  /// One env step's answer: rewards and ended episodes.
  void recordStep(const StepResult& result);
  /// Completes `stats` with the iteration's figures (reward per step, returns, observation
  /// means), writes the CSV row and the progress line and updates the summary; starts the next
  /// iteration's sums. Returns true when the iteration is the best so far (best_by).
  bool endIteration(IterationStats& stats);

 private:
  LoggerOptions options_;
  TrainingSummary& summary_;
  ProgressCsv csv_;
  EpisodeTracker tracker_;
  std::function<void(const std::string&)> sink_;
  double reward_sum_ = 0.0;
  std::int64_t reward_count_ = 0;
  std::int64_t outcomes_[3] = {0, 0, 0};  ///< This iteration's ended episodes per Outcome.
  std::vector<double> obs_sum_;           ///< Per component: sum over this rollout's late samples.
  std::int64_t obs_count_ = 0;            ///< Late samples (env steps) in this rollout.
};

}  // namespace ppo
}  // namespace jetbot_rl
