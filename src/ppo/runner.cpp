#include "jetbot_rl/ppo/runner.h"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "jetbot_rl/ppo/progress_csv.h"

namespace jetbot_rl {
namespace ppo {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

torch::Tensor floats(const std::vector<float>& v, int rows, int cols) {
  return torch::from_blob(const_cast<float*>(v.data()), {rows, cols}, torch::kFloat).clone();
}

torch::Tensor flags(const std::vector<std::uint8_t>& v) {
  return torch::from_blob(const_cast<std::uint8_t*>(v.data()), {static_cast<int64_t>(v.size())},
                          torch::kUInt8)
      .to(torch::kFloat);
}

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
    << "\nbest_mean_reward_per_step: " << fixed(s.best_reward, 4)
    << "\nmean_env_steps_per_s: " << fixed(s.mean_env_steps_per_s, 0)
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

OnPolicyRunner::OnPolicyRunner(VecEnv& env, const PpoConfig& config, const RunnerOptions& options)
    : env_(env), config_(config), options_(options) {
  log_ = [](const std::string& line) { std::cout << line << std::endl; };
  validate(config_);
  const EnvInfo& info = env_.info();
  const std::int64_t batch = static_cast<std::int64_t>(config_.num_steps_per_env) * info.num_envs;
  if (config_.num_mini_batches > batch) {
    throw ConfigError("invalid num_mini_batches = " + std::to_string(config_.num_mini_batches) +
                      ": must be <= num_steps_per_env x num_envs = " + std::to_string(batch));
  }
  if (options_.iterations < 1) {
    throw ConfigError("invalid iterations = " + std::to_string(options_.iterations) +
                      ": must be >= 1");
  }
  if (options_.save_interval < 1) {
    throw ConfigError("invalid save_interval = " + std::to_string(options_.save_interval) +
                      ": must be >= 1");
  }
  if (options_.run_dir.empty()) throw ConfigError("invalid run_dir = '': must be a directory");
  if (options_.obs_stats_from_step < -1 ||
      options_.obs_stats_from_step >= std::max(1, info.max_episode_length)) {
    throw ConfigError(
        "invalid obs_stats_from_step = " + std::to_string(options_.obs_stats_from_step) +
        ": must be -1 (second half of an episode) or in [0, max_episode_length = " +
        std::to_string(info.max_episode_length) + ")");
  }
  obs_from_step_ = options_.obs_stats_from_step >= 0 ? options_.obs_stats_from_step
                                                     : info.max_episode_length / 2;
  if (static_cast<int>(info.observation_names.size()) == info.obs_dim) {
    obs_names_ = info.observation_names;
  } else {
    for (int k = 0; k < info.obs_dim; ++k) obs_names_.push_back("obs" + std::to_string(k));
  }

  CheckpointMeta meta;
  if (!options_.resume.empty()) {
    meta = readCheckpointMeta(options_.resume);
    if (!sameArchitecture(meta.config, config_)) {
      log_(
          "resume: the checkpoint's network (hidden dims, activation) differs from the "
          "parameters; using the checkpoint's");
      config_.actor_hidden_dims = meta.config.actor_hidden_dims;
      config_.critic_hidden_dims = meta.config.critic_hidden_dims;
      config_.activation = meta.config.activation;
    }
    config_.normalize_observations = meta.config.normalize_observations;
  }
  torch::manual_seed(static_cast<std::uint64_t>(config_.seed));
  ppo_ = std::make_unique<Ppo>(info.obs_dim, info.action_dim, config_);
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
  scaler_ =
      std::make_unique<ActionScaler>(info.action_low, info.action_high, config_.action_squash);
  storage_ = std::make_unique<RolloutStorage>(config_.num_steps_per_env, info.num_envs,
                                              info.obs_dim, info.action_dim);
  tracker_ = std::make_unique<EpisodeTracker>(info.num_envs);
}

double OnPolicyRunner::collect() {
  const EnvInfo& info = env_.info();
  const int n = info.num_envs, obs_dim = info.obs_dim;
  Ppo& ppo = *ppo_;
  double reward_sum = 0.0;
  obs_sum_.assign(obs_dim, 0.0);
  obs_count_ = 0;
  for (int t = 0; t < config_.num_steps_per_env; ++t) {
    // The observations the policy acts on, late in their episodes (raw, not normalised).
    for (int i = 0; i < n; ++i) {
      if (episode_step_[i] < obs_from_step_) continue;
      for (int k = 0; k < obs_dim; ++k) obs_sum_[k] += batch_->observations[i * obs_dim + k];
      ++obs_count_;
    }
    const torch::Tensor obs = floats(batch_->observations, n, obs_dim);
    ppo.normalizer()->update(obs);
    const torch::Tensor obs_n = ppo.normalizer()->normalize(obs);
    const ActionSample s = ppo.model()->act(obs_n);
    scaler_->toEnv(s.actions, actions_);

    batch_ = &env_.step(actions_);  // throws Interrupted / Error

    const torch::Tensor rewards =
        torch::from_blob(const_cast<float*>(batch_->rewards.data()), {n}, torch::kFloat).clone();
    const torch::Tensor terminated = flags(batch_->terminated);
    torch::Tensor truncated = flags(batch_->truncated);
    torch::Tensor truncated_values = torch::zeros({n});
    // Time-outs bootstrap with V(final observation), never as terminal states.
    std::vector<int64_t> rows, envs;
    for (std::size_t k = 0; k < batch_->reset_env_ids.size(); ++k) {
      const std::uint32_t id = batch_->reset_env_ids[k];
      if (batch_->truncated[id] && !batch_->terminated[id]) {
        rows.push_back(static_cast<int64_t>(k));
        envs.push_back(id);
      }
    }
    for (int i = 0; i < n; ++i) {
      if (batch_->truncated[i] && !batch_->terminated[i] &&
          std::find(envs.begin(), envs.end(), i) == envs.end()) {
        throw Error("env " + std::to_string(i) +
                    " is truncated but has no final observation in reset_env_ids");
      }
    }
    if (!rows.empty()) {
      torch::NoGradGuard no_grad;
      const int ended = static_cast<int>(batch_->reset_env_ids.size());
      const torch::Tensor finals = floats(batch_->final_observations, ended, obs_dim)
                                       .index_select(0, torch::tensor(rows, torch::kLong));
      const torch::Tensor v = ppo.model()->value(ppo.normalizer()->normalize(finals));
      truncated_values.index_copy_(0, torch::tensor(envs, torch::kLong), v);
    }
    tracker_->add(*batch_);
    reward_sum += rewards.sum().item<double>();
    for (int i = 0; i < n; ++i) ++episode_step_[i];
    for (std::uint32_t id : batch_->reset_env_ids) episode_step_[id] = 0;

    // Staggering: cut the first episode of the envs due now, as a time-out bootstrapped with
    // V(observation before the reset); the cut episode's return is not counted.
    ++steps_since_reset_;
    std::vector<std::uint32_t> cut;
    for (std::size_t i = 0; i < cut_at_.size(); ++i) {
      if (cut_at_[i] == steps_since_reset_ && !batch_->truncated[i] && !batch_->terminated[i]) {
        cut.push_back(static_cast<std::uint32_t>(i));
      }
    }
    if (!cut.empty()) {
      torch::NoGradGuard no_grad;
      const torch::Tensor ids = torch::tensor(std::vector<int64_t>(cut.begin(), cut.end()));
      const torch::Tensor before = floats(batch_->observations, n, obs_dim).index_select(0, ids);
      const torch::Tensor v = ppo.model()->value(ppo.normalizer()->normalize(before));
      truncated_values.index_copy_(0, ids, v);
      truncated.index_fill_(0, ids, 1.0);
      tracker_->discard(cut);
      for (std::uint32_t id : cut) episode_step_[id] = 0;
      batch_ = &env_.resetEnvs(cut);
    }
    storage_->add(t, obs_n, s.actions, s.log_probs, s.values, s.mean, s.std, rewards, terminated,
                  truncated, truncated_values);
  }
  torch::NoGradGuard no_grad;
  const torch::Tensor last_obs = floats(batch_->observations, n, obs_dim);
  const torch::Tensor last_values = ppo.model()->value(ppo.normalizer()->normalize(last_obs));
  storage_->computeReturns(last_values, config_.gamma, config_.lam);
  return reward_sum;
}

void OnPolicyRunner::save(const std::string& path, double elapsed_s) {
  CheckpointMeta meta;
  meta.iteration = iteration_;
  meta.env_steps = env_steps_;
  meta.best_reward = best_reward_;
  meta.learning_rate = ppo_->learningRate();
  meta.obs_dim = env_.info().obs_dim;
  meta.action_dim = env_.info().action_dim;
  meta.config = config_;
  meta.elapsed_s = elapsed_s;
  saveCheckpoint(path, *ppo_, meta);
}

TrainingSummary OnPolicyRunner::learn() {
  namespace fs = std::filesystem;
  const EnvInfo& info = env_.info();
  const fs::path run_dir(options_.run_dir);
  const fs::path checkpoints = run_dir / "checkpoints";
  fs::create_directories(checkpoints);
  const std::string latest = (checkpoints / "latest.pt").string();
  const std::string best = (checkpoints / "best.pt").string();
  {
    std::ofstream config_file(run_dir / "config.yaml");
    config_file << "# PPO hyper-parameters\n" << toYaml(config_) << options_.extra_config;
  }
  const bool resumed = !options_.resume.empty();
  ProgressCsv csv((run_dir / "progress.csv").string(), resumed ? iteration_ : -1, obs_names_);

  TrainingSummary summary;
  summary.run_dir = run_dir.string();
  summary.target_reward = options_.target_reward;
  summary.final_episode_return = std::nan("");
  const std::int64_t first_iteration = iteration_;
  const std::int64_t steps_per_iteration =
      static_cast<std::int64_t>(config_.num_steps_per_env) * info.num_envs;
  const auto start = Clock::now();
  double elapsed_at_save = elapsed_before_;
  auto elapsed = [&] { return elapsed_before_ + seconds(start, Clock::now()); };

  if (resumed) {
    log_("resumed from " + options_.resume + " at iteration " + std::to_string(iteration_) + ", " +
         std::to_string(env_steps_) + " env steps");
    if (iteration_ >= options_.iterations) {
      log_("nothing to train: the checkpoint has " + std::to_string(iteration_) +
           " iterations and iterations is " + std::to_string(options_.iterations) +
           "; raise iterations to continue");
    }
  }
  try {
    batch_ = &env_.reset(resumed ? config_.seed + iteration_ : config_.seed);
    steps_since_reset_ = 0;
    episode_step_.assign(info.num_envs, 0);
    cut_at_.clear();
    if (config_.stagger_episodes) {
      const std::int64_t length = std::max(1, info.max_episode_length - 1);
      for (int i = 0; i < info.num_envs; ++i) cut_at_.push_back(i * length / info.num_envs);
    }
    while (iteration_ < options_.iterations) {
      const auto t0 = Clock::now();
      const double reward_sum = collect();
      const auto t1 = Clock::now();
      const UpdateStats update = ppo_->update(*storage_);
      const auto t2 = Clock::now();

      ++iteration_;
      env_steps_ += steps_per_iteration;
      IterationStats s;
      s.iteration = iteration_;
      s.iterations = options_.iterations;
      s.env_steps = env_steps_;
      s.mean_reward_per_step = reward_sum / static_cast<double>(steps_per_iteration);
      s.mean_episode_return = tracker_->meanReturn();
      s.collection_s = seconds(t0, t1);
      s.update_s = seconds(t1, t2);
      s.env_steps_per_s = steps_per_iteration / seconds(t0, t2);
      s.elapsed_s = elapsed();
      const double per_iteration = seconds(start, t2) / (iteration_ - first_iteration);
      s.time_left_s = per_iteration * (options_.iterations - iteration_);
      s.update = update;
      s.action_std = ppo_->model()->actionStd().mean().item<double>();
      s.episodes = tracker_->episodes();
      s.obs_names = obs_names_;
      s.obs_samples = obs_count_;
      for (double sum : obs_sum_) {
        s.obs_means.push_back(obs_count_ > 0 ? sum / static_cast<double>(obs_count_)
                                             : std::nan(""));
      }

      csv.append(s);
      log_(progressLine(s));
      if (s.mean_reward_per_step >= options_.target_reward && summary.target_iteration < 0) {
        summary.target_iteration = iteration_;
        summary.target_env_steps = env_steps_;
        summary.target_elapsed_s = s.elapsed_s;
      }
      summary.final_reward = s.mean_reward_per_step;
      summary.final_episode_return = s.mean_episode_return;
      const bool improved = s.mean_reward_per_step > best_reward_;
      if (improved) best_reward_ = s.mean_reward_per_step;
      elapsed_at_save = s.elapsed_s;
      if (improved) save(best, elapsed_at_save);
      if (iteration_ % options_.save_interval == 0 || iteration_ == options_.iterations) {
        save(latest, elapsed_at_save);
      }
      if (on_iteration_) on_iteration_(s);
    }
  } catch (const Interrupted& e) {
    summary.interrupted = true;
    log_(std::string("interrupted (") + e.what() + "): saving " + latest);
  } catch (const Error& e) {
    summary.error = e.what();
    log_(std::string("training stopped: ") + e.what() + "; saving " + latest);
  }
  if (summary.interrupted || !summary.error.empty()) {
    save(latest, elapsed_at_save);  // the model after the last completed update
  }
  summary.iterations = iteration_;
  summary.env_steps = env_steps_;
  summary.elapsed_s = elapsed();
  summary.best_reward = best_reward_;
  const double session_s = seconds(start, Clock::now());
  summary.mean_env_steps_per_s =
      session_s > 0 ? (iteration_ - first_iteration) * steps_per_iteration / session_s : 0.0;
  std::ofstream(run_dir / "summary.yaml") << describeSummary(summary) << "\n";
  return summary;
}

}  // namespace ppo
}  // namespace jetbot_rl
