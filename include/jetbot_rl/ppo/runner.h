#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "jetbot_rl/env/vec_env.h"
#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/runner_options.h"
#include "jetbot_rl/ppo/training_logger.h"

namespace jetbot_rl {
namespace ppo {

/// Episode steps that stagger num_envs starts evenly over an episode (rsl_rl randomises them):
/// env i starts at i x (max_episode_length - 1) / num_envs.
std::vector<std::uint32_t> staggeredStarts(int num_envs, int max_episode_length);

/**
 * On-policy training loop (rsl_rl's OnPolicyRunner): resets the env once (staggered starts),
 * then per iteration collects num_steps_per_env steps with Ppo::act / processEnvStep, computes
 * returns, updates, logs (TrainingLogger) and saves checkpoints. Knows the env only through
 * VecEnv.
 */
class Ppo;  // ppo.h (libtorch's headers): a node that runs a runner need not parse them

class OnPolicyRunner {
 public:
  /// Seeds torch with config.seed and builds the algorithm, or loads options.resume. Throws
  /// ConfigError (bad hyper-parameter) or Error (unreadable checkpoint).
  OnPolicyRunner(VecEnv& env, const PpoConfig& config, const RunnerOptions& options);
  ~OnPolicyRunner();

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
