#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/checkpoint.h"
#include "jetbot_rl/ppo/episode_tracker.h"
#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/vec_env.h"

namespace jetbot_rl {
namespace ppo {

/// How a training run is driven and where it writes.
struct RunnerOptions {
  std::int64_t iterations = 100;  ///< The run ends after this many iterations (resume included).
  std::string run_dir;            ///< Run directory (created): CSV, config, checkpoints.
  std::string resume;             ///< Checkpoint to continue from; empty: a new run.
  int save_interval = 10;         ///< Save checkpoints/latest.pt every this many iterations.
  double target_reward = 0.54;    ///< Reported: first iteration with mean reward/step >= this.
  std::string extra_config;       ///< YAML appended to config.yaml (trainer params, env spec).
  /// obs_mean_* columns: mean of each observation component over the rollout's samples taken at
  /// this step of their episode or later (0: the reset's observation) [control steps]; -1: the
  /// second half of an episode, max_episode_length / 2.
  int obs_stats_from_step = -1;
};

/// The final figures of a run.
struct TrainingSummary {
  bool interrupted = false;     ///< Stopped early (Ctrl-C); checkpoints/latest.pt was saved.
  std::string error;            ///< Non-empty: the run failed (e.g. the env stopped answering).
  std::int64_t iterations = 0;  ///< Completed iterations.
  std::int64_t env_steps = 0;
  double elapsed_s = 0.0;
  double final_reward = 0.0;          ///< Mean reward per step of the last iteration [m/s].
  double final_episode_return = 0.0;  ///< Mean return of the last 100 episodes.
  double best_reward = 0.0;           ///< Best iteration's mean reward per step.
  double target_reward = 0.0;
  std::int64_t target_iteration = -1;  ///< First iteration reaching target_reward; -1: never.
  std::int64_t target_env_steps = -1;
  double target_elapsed_s = -1.0;
  double mean_env_steps_per_s = 0.0;  ///< Env steps / wall time of this session.
  std::string run_dir;
};

/// The final figures as "name: value" lines (printed at the end and written to summary.yaml).
std::string describeSummary(const TrainingSummary& summary);

/**
 * On-policy training loop (rsl_rl's OnPolicyRunner): collects num_steps_per_env steps of every
 * env with the stochastic policy, computes GAE with time-out bootstrapping, updates with PPO,
 * logs, writes progress.csv and checkpoints. Knows the env only through VecEnv.
 */
class OnPolicyRunner {
 public:
  /// Seeds torch with config.seed and builds the model, or loads options.resume. Throws
  /// ConfigError (bad hyper-parameter) or Error (unreadable checkpoint).
  OnPolicyRunner(VecEnv& env, const PpoConfig& config, const RunnerOptions& options);

  /// Where progress lines and notes go (default: stdout).
  void setLogger(std::function<void(const std::string&)> logger) { log_ = std::move(logger); }
  /// Called after every iteration, after its CSV row is written.
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
  /// One rollout into storage_; returns the sum of rewards. Sums the late observations into
  /// obs_sum_ and obs_count_.
  double collect();
  /// Saves the state after the last completed update; `elapsed_s` = training time so far.
  void save(const std::string& path, double elapsed_s);

  VecEnv& env_;
  PpoConfig config_;
  RunnerOptions options_;
  std::unique_ptr<Ppo> ppo_;
  std::unique_ptr<ActionScaler> scaler_;
  std::unique_ptr<RolloutStorage> storage_;
  std::unique_ptr<EpisodeTracker> tracker_;
  std::function<void(const std::string&)> log_;
  std::function<void(const IterationStats&)> on_iteration_;

  std::int64_t iteration_ = 0, env_steps_ = 0;
  double elapsed_before_ = 0.0;  ///< Wall time of earlier sessions (resume).
  double best_reward_ = -1e300;
  const EnvBatch* batch_ = nullptr;   ///< The env's current state.
  std::vector<std::int64_t> cut_at_;  ///< Per env: step (since the reset) to cut its first
                                      ///< episode (stagger_episodes); 0: none.
  std::int64_t steps_since_reset_ = 0;
  std::vector<float> actions_;
  std::vector<std::string> obs_names_;      ///< EnvInfo::observation_names, or obs0, obs1, ...
  int obs_from_step_ = 0;                   ///< Resolved RunnerOptions::obs_stats_from_step.
  std::vector<std::int64_t> episode_step_;  ///< Per env: steps since its episode began.
  std::vector<double> obs_sum_;  ///< Per component: sum over this rollout's late samples.
  std::int64_t obs_count_ = 0;   ///< Late samples (env steps) in this rollout.
};

}  // namespace ppo
}  // namespace jetbot_rl
