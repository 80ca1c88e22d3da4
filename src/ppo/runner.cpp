#include "jetbot_rl/ppo/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"
#include "jetbot_rl/ppo/ppo_losses.h"
#include "jetbot_rl/ppo/progress_csv.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

std::vector<std::uint32_t> staggeredStarts(int num_envs, int max_episode_length) {
  std::vector<std::uint32_t> starts;
  const std::int64_t length = std::max(1, max_episode_length - 1);
  for (int i = 0; i < num_envs; ++i)
    starts.push_back(static_cast<std::uint32_t>(i * length / num_envs));
  return starts;
}

OnPolicyRunner::OnPolicyRunner(VecEnv& env, const PpoConfig& config, const RunnerOptions& options)
    : env_(env), config_(config), options_(options) {
  sink_ = [](const std::string& line) { std::cout << line << std::endl; };
  validate(config_);
  const BatchSpec& info = env_.spec();
  const std::int64_t batch = static_cast<std::int64_t>(config_.num_steps_per_env) * info.num_envs;
  if (config_.num_mini_batches > batch) {
    throw ConfigError("invalid num_mini_batches = " + std::to_string(config_.num_mini_batches) +
                      ": must be <= num_steps_per_env x num_envs = " + std::to_string(batch));
  }
  validateFields(options_);
  if (options_.run_dir.empty()) throwInvalid("run_dir", "''", "must name a directory");
  if (options_.obs_stats_from_step >= std::max(1, info.max_episode_length)) {
    throw ConfigError(
        "invalid obs_stats_from_step = " + std::to_string(options_.obs_stats_from_step) +
        ": must be -1 (second half of an episode) or in [0, max_episode_length = " +
        std::to_string(info.max_episode_length) + ")");
  }
  CheckpointMeta meta;
  if (!options_.resume.empty()) {
    meta = readCheckpointMeta(options_.resume);
    if (!sameArchitecture(meta.config, config_)) {
      sink_(
          "resume: the checkpoint's network (hidden dims, activation, memory) differs from the "
          "parameters; using the checkpoint's");
      copyArchitecture(meta.config, config_);
    }
    config_.normalize_observations = meta.config.normalize_observations;
  }
  torch::manual_seed(static_cast<std::uint64_t>(config_.seed));
  ppo_ = std::make_unique<Ppo>(info, config_);
  if (!options_.resume.empty()) {
    meta = loadCheckpoint(options_.resume, *ppo_);
    iteration_ = meta.iteration;
    env_steps_ = meta.env_steps;
    elapsed_before_ = meta.elapsed_s;
    best_reward_ = meta.best_reward;
    // A different random stream from the one the first session used at this point.
    torch::manual_seed(static_cast<std::uint64_t>(config_.seed) * 1000003ULL +
                       static_cast<std::uint64_t>(iteration_));
  }
}

OnPolicyRunner::~OnPolicyRunner() = default;

void OnPolicyRunner::save(const std::string& path, double elapsed_s, double best_reward) {
  CheckpointMeta meta;
  meta.iteration = iteration_;
  meta.env_steps = env_steps_;
  meta.best_reward = best_reward;
  meta.learning_rate = ppo_->learningRate();
  meta.obs_dim = env_.spec().obs_dim;
  meta.action_dim = env_.spec().action_dim;
  meta.config = config_;
  meta.elapsed_s = elapsed_s;
  meta.spec = env_.spec();
  meta.spec.num_envs = 0;  // a property of the run, not of the policy
  saveCheckpoint(path, *ppo_, meta);
}

void OnPolicyRunner::exportBest(const std::string& best, const std::string& path,
                                const TrainingLogger& logger) const {
  if (!std::filesystem::is_regular_file(best)) return;
  try {
    Policy policy(best);
    policy.setActionLimits(env_.spec().action_low, env_.spec().action_high);
    policy.exportTorchScript(path, env_.spec());
    logger.log("exported the best policy as TorchScript: " + path);
  } catch (const Error& e) {
    logger.log(std::string("could not export the policy: ") + e.what());
  }
}

TrainingSummary OnPolicyRunner::learn() {
  namespace fs = std::filesystem;
  const BatchSpec& spec = env_.spec();
  const fs::path run_dir(options_.run_dir);
  const fs::path checkpoints = run_dir / "checkpoints";
  fs::create_directories(checkpoints);
  const std::string latest = (checkpoints / "latest.pt").string();
  const std::string best = (checkpoints / "best.pt").string();
  const bool last_is_best = options_.best_by == BestBy::kLast;
  {
    std::ofstream config_file(run_dir / "config.yaml");
    config_file << "# PPO hyper-parameters\n" << toYaml(config_) << options_.extra_config;
  }
  const bool resumed = !options_.resume.empty();

  LoggerOptions log_options;
  log_options.csv_path = (run_dir / "progress.csv").string();
  log_options.keep_rows = resumed ? iteration_ : -1;
  log_options.target_reward = options_.target_reward;
  log_options.best_by = options_.best_by;
  log_options.obs_stats_from_step = options_.obs_stats_from_step >= 0 ? options_.obs_stats_from_step
                                                                      : spec.max_episode_length / 2;
  if (static_cast<int>(spec.observation_names.size()) == spec.obs_dim) {
    log_options.obs_names = spec.observation_names;
  } else {
    for (int k = 0; k < spec.obs_dim; ++k)
      log_options.obs_names.push_back("obs" + std::to_string(k));
  }
  TrainingSummary summary;
  summary.run_dir = run_dir.string();
  summary.best_reward = best_reward_;
  TrainingLogger logger(spec.num_envs, log_options, summary);
  logger.setSink(sink_);

  const std::int64_t first_iteration = iteration_;
  const std::int64_t steps_per_iteration =
      static_cast<std::int64_t>(config_.num_steps_per_env) * spec.num_envs;
  const auto start = Clock::now();
  double elapsed_at_save = elapsed_before_;
  auto elapsed = [&] { return elapsed_before_ + seconds(start, Clock::now()); };

  if (resumed) {
    logger.log("resumed from " + options_.resume + " at iteration " + std::to_string(iteration_) +
               ", " + std::to_string(env_steps_) + " env steps");
    if (iteration_ >= options_.iterations) {
      logger.log("nothing to train: the checkpoint has " + std::to_string(iteration_) +
                 " iterations and iterations is " + std::to_string(options_.iterations) +
                 "; raise iterations to continue");
    }
  }
  std::optional<IterationStats> last;  // the final iteration's, reported at the very end
  try {
    const std::vector<std::uint32_t> starts =
        config_.stagger_episodes ? staggeredStarts(spec.num_envs, spec.max_episode_length)
                                 : std::vector<std::uint32_t>();
    const StepResult* state =
        &env_.reset(resumed ? config_.seed + iteration_ : config_.seed, starts);
    logger.startedAt(starts);
    while (iteration_ < options_.iterations) {
      const auto t0 = Clock::now();
      for (int t = 0; t < config_.num_steps_per_env; ++t) {
        logger.recordObservations(*state);
        state = &env_.step(ppo_->act(*state));  // throws Interrupted / Error
        ppo_->processEnvStep(*state);
        logger.recordStep(*state);
      }
      ppo_->computeReturns(*state);
      const auto t1 = Clock::now();
      ppo_->setLearningRateCeiling(
          learningRateCeiling(ppo_->config(), iteration_, options_.iterations));
      const UpdateStats update = ppo_->update();
      const auto t2 = Clock::now();

      ++iteration_;
      env_steps_ += steps_per_iteration;
      IterationStats s;
      s.iteration = iteration_;
      s.iterations = options_.iterations;
      s.env_steps = env_steps_;
      s.collection_s = seconds(t0, t1);
      s.update_s = seconds(t1, t2);
      s.env_steps_per_s = steps_per_iteration / seconds(t0, t2);
      s.elapsed_s = elapsed();
      s.time_left_s = seconds(start, t2) / (iteration_ - first_iteration) *
                      static_cast<double>(options_.iterations - iteration_);
      s.update = update;
      s.action_std = ppo_->actionStd();
      const bool improved = logger.endIteration(s);
      elapsed_at_save = s.elapsed_s;
      const bool save_point =
          iteration_ % options_.save_interval == 0 || iteration_ == options_.iterations;
      // best_by last: best.pt is the last iteration, written with latest.pt, not at every one.
      if (improved && (!last_is_best || save_point))
        save(best, elapsed_at_save, summary.best_reward);
      if (save_point) save(latest, elapsed_at_save, summary.best_reward);
      // The last iteration's callback comes after summary.yaml and the export, so that whoever
      // waits for it finds the run's files complete.
      if (iteration_ < options_.iterations) {
        if (on_iteration_) on_iteration_(s);
      } else {
        last = s;
      }
    }
  } catch (const Interrupted& e) {
    summary.interrupted = true;
    logger.log(std::string("interrupted (") + e.what() + "): saving " + latest);
  } catch (const Error& e) {
    summary.error = e.what();
    logger.log(std::string("training stopped: ") + e.what() + "; saving " + latest);
  }
  if (summary.interrupted || !summary.error.empty()) {
    save(latest, elapsed_at_save, summary.best_reward);  // the model after the last update
    if (last_is_best) save(best, elapsed_at_save, summary.best_reward);
  }
  summary.iterations = iteration_;
  summary.env_steps = env_steps_;
  summary.elapsed_s = elapsed();
  const double session_s = seconds(start, Clock::now());
  summary.mean_env_steps_per_s =
      session_s > 0 ? (iteration_ - first_iteration) * steps_per_iteration / session_s : 0.0;
  std::ofstream(run_dir / "summary.yaml") << describeSummary(summary) << "\n";
  exportBest(best, (run_dir / "exported" / "policy.pt").string(), logger);
  if (last && on_iteration_) on_iteration_(*last);
  return summary;
}

}  // namespace ppo
}  // namespace jetbot_rl
