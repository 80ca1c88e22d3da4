#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "jetbot_rl/env/vec_env.h"
#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"
#include "jetbot_rl/ppo/training_logger.h"

namespace jetbot_rl {
namespace ppo {

/// How a training run is driven and where it writes.
struct RunnerOptions {
  std::int64_t iterations = 100;  ///< The run ends after this many iterations (resume included).
  std::string run_dir;            ///< Run directory (created): CSV, config, checkpoints.
  std::string resume;             ///< Checkpoint to continue from; empty: a new run.
  int save_interval = 10;         ///< Save checkpoints/latest.pt every this many iterations.
  double target_reward = 0.54;    ///< Reported: first iteration with mean reward/step >= this.
  BestBy best_by = BestBy::kRewardPerStep;  ///< What makes checkpoints/best.pt.
  std::string extra_config;  ///< YAML appended to config.yaml (trainer params, env spec).
  /// obs_mean_* columns: mean of each observation component over the rollout's samples taken at
  /// this step of their episode or later (0: the reset's observation) [control steps]; -1: the
  /// second half of an episode, max_episode_length / 2.
  int obs_stats_from_step = -1;
};

/// The parameters among RunnerOptions (extra_config is not one), with their rules.
template <typename C, typename V>
IfConfig<C, RunnerOptions> visitFields(C& c, V&& v) {
  v("iterations", c.iterations, atLeast<std::int64_t>(1),
    "The run ends after this many iterations (a resumed run's included).");
  v("run_dir", c.run_dir, AnyValue{"", "empty: ~/.ros/jetbot_rl/TIME_seedSEED"},
    "Run directory (created): progress.csv, config.yaml, checkpoints, exported policy.");
  v("resume", c.resume, AnyValue{"", "empty: a new run"},
    "Checkpoint file or run directory (its checkpoints/latest.pt) to continue from.");
  v("save_interval", c.save_interval, atLeast(1),
    "Write checkpoints/latest.pt every this many iterations (and at the end).");
  v("target_reward", c.target_reward,
    Range<double>{-1e300, 1e300, false, false, "m/s", "reported only"},
    "Reported: the first iteration whose mean reward per step reaches this.");
  v("best_by", c.best_by, AnyValue{},
    "Which iteration's policy is checkpoints/best.pt (and exported/policy.pt): reward_per_step, "
    "the highest mean reward per step of an iteration; episode_return, the highest mean return "
    "of the last 100 episodes (steadier where the reward per step swings with the episodes' "
    "phase, as with rounds of robots: docs/team.md); last, the last iteration (with a "
    "curriculum, whose later iterations are harder, rewards of different iterations do not "
    "compare).");
  v("obs_stats_from_step", c.obs_stats_from_step,
    atLeast(-1, "control steps", "-1: max_episode_length / 2"),
    "progress.csv's obs_mean_<name> columns: mean of each observation over the rollout's "
    "samples at this step of their episode or later.");
}

inline const EnumNameList<BestBy>& enumNames(BestBy) {
  static const EnumNameList<BestBy> names{{BestBy::kRewardPerStep, "reward_per_step"},
                                          {BestBy::kEpisodeReturn, "episode_return"},
                                          {BestBy::kLast, "last"}};
  return names;
}

/// Episode steps that stagger num_envs starts evenly over an episode (rsl_rl randomises them):
/// env i starts at i x (max_episode_length - 1) / num_envs.
std::vector<std::uint32_t> staggeredStarts(int num_envs, int max_episode_length);

/**
 * On-policy training loop (rsl_rl's OnPolicyRunner): resets the env once (staggered starts),
 * then per iteration collects num_steps_per_env steps with Ppo::act / processEnvStep, computes
 * returns, updates, logs (TrainingLogger) and saves checkpoints. Knows the env only through
 * VecEnv.
 */
class OnPolicyRunner {
 public:
  /// Seeds torch with config.seed and builds the algorithm, or loads options.resume. Throws
  /// ConfigError (bad hyper-parameter) or Error (unreadable checkpoint).
  OnPolicyRunner(VecEnv& env, const PpoConfig& config, const RunnerOptions& options);

  /// Where progress lines and notes go (default: stdout).
  void setLogger(std::function<void(const std::string&)> sink) { sink_ = std::move(sink); }
  /// Called after every iteration, after its CSV row and checkpoints are written; for the run's
  /// last iteration after summary.yaml and exported/policy.pt too.
  void setIterationCallback(std::function<void(const IterationStats&)> cb) {
    on_iteration_ = std::move(cb);
  }

  /// Trains until options.iterations, an Interrupted from the env (saves and returns) or an
  /// env Error (saves and returns it in summary.error).
  TrainingSummary learn();

  Ppo& ppo() { return *ppo_; }
  const PpoConfig& config() const { return config_; }
  std::int64_t iteration() const { return iteration_; }

 private:
  /// Writes checkpoint `best` as a TorchScript policy at `path` (logged; an error is logged too).
  void exportBest(const std::string& best, const std::string& path,
                  const TrainingLogger& logger) const;
  /// Saves the state after the last completed update; `elapsed_s` = training time so far.
  void save(const std::string& path, double elapsed_s, double best_reward);

  VecEnv& env_;
  PpoConfig config_;
  RunnerOptions options_;
  std::unique_ptr<Ppo> ppo_;
  std::function<void(const std::string&)> sink_;
  std::function<void(const IterationStats&)> on_iteration_;
  std::int64_t iteration_ = 0, env_steps_ = 0;
  double elapsed_before_ = 0.0;  ///< Wall time of earlier sessions (resume).
  double best_reward_ = -1e300;  ///< Of earlier sessions (resume).
};

}  // namespace ppo
}  // namespace jetbot_rl
