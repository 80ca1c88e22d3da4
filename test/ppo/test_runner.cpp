// The training loop on a toy VecEnv (no ROS): it learns, is deterministic for a seed, resumes,
// and saves on interruption.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "jetbot_rl/ppo/checkpoint.h"
#include "jetbot_rl/ppo/runner.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// A Jetbot-like toy: wheel targets [rad/s] in +-20 drive a first-order forward speed v and
/// yaw rate w; obs = [v, w, 0]; reward = |v| [m/s] (at most 0.6); time-out after 20 steps
/// (episode step max_episode_length - 1, as the core).
class ToyEnv : public VecEnv {
 public:
  explicit ToyEnv(int num_envs, std::int64_t interrupt_at = -1) : interrupt_at_(interrupt_at) {
    spec_.num_envs = num_envs;
    spec_.obs_dim = 3;
    spec_.action_dim = 2;
    spec_.action_low = {-20.0f, -20.0f};
    spec_.action_high = {20.0f, 20.0f};
    spec_.control_dt = 1.0 / 60.0;
    spec_.max_episode_length = 21;
    spec_.task = "toy";
  }
  const BatchSpec& spec() const override { return spec_; }
  void setObservationNames(const std::vector<std::string>& names) {
    spec_.observation_names = names;
  }
  const StepResult& reset(std::int64_t, const std::vector<std::uint32_t>& episode_steps) override {
    const auto n = static_cast<std::size_t>(spec_.num_envs);
    b_ = StepResult();
    b_.observations.assign(n * 3, 0.0f);
    b_.rewards.assign(n, 0.0f);
    b_.terminated.assign(n, 0);
    b_.truncated.assign(n, 0);
    b_.episode_steps.assign(n, 0);
    if (!episode_steps.empty()) b_.episode_steps = episode_steps;
    starts = episode_steps;
    return b_;
  }
  void stepAsync(const std::vector<float>& a) override { actions_ = a; }
  const StepResult& stepWait() override {
    if (interrupt_at_ >= 0 && static_cast<std::int64_t>(b_.step) == interrupt_at_) {
      throw Interrupted("test interrupt");
    }
    const std::vector<float>& a = actions_;
    const auto n = static_cast<std::size_t>(spec_.num_envs);
    EXPECT_EQ(a.size(), n * 2);
    ++b_.step;
    b_.reset_env_ids.clear();
    b_.final_observations.clear();
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_LE(std::abs(a[2 * i]), 20.0f);
      float* o = &b_.observations[3 * i];
      o[0] = 0.5f * o[0] + 0.5f * 0.03f * 0.5f * (a[2 * i] + a[2 * i + 1]);
      o[1] = 0.5f * o[1] + 0.5f * 0.03f * (a[2 * i + 1] - a[2 * i]) / 0.1125f;
      b_.rewards[i] = std::abs(o[0]);
      b_.truncated[i] = ++b_.episode_steps[i] >= 20;
      if (b_.truncated[i]) {
        b_.reset_env_ids.push_back(static_cast<std::uint32_t>(i));
        b_.final_observations.insert(b_.final_observations.end(), o, o + 3);
        o[0] = o[1] = o[2] = 0.0f;
        b_.episode_steps[i] = 0;
        ends.emplace_back(b_.step, i);
      }
    }
    return b_;
  }

  std::vector<std::uint32_t> starts;                          ///< episode_steps of the last reset
  std::vector<std::pair<std::uint64_t, std::uint32_t>> ends;  ///< (step, env) of every time-out

 private:
  BatchSpec spec_;
  StepResult b_;
  std::vector<float> actions_;
  std::int64_t interrupt_at_;
};

PpoConfig toyConfig() {
  PpoConfig c;
  c.seed = 3;
  c.num_steps_per_env = 16;
  c.num_mini_batches = 2;
  return c;
}

std::string runDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_runner" / name;
  std::filesystem::remove_all(dir);
  return dir.string();
}

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TrainingSummary train(VecEnv& env, const std::string& dir, std::int64_t iterations,
                      const std::string& resume = "", BestBy best_by = BestBy::kRewardPerStep) {
  RunnerOptions o;
  o.iterations = iterations;
  o.run_dir = dir;
  o.resume = resume;
  o.save_interval = 2;
  o.best_by = best_by;
  OnPolicyRunner runner(env, toyConfig(), o);
  runner.setLogger([](const std::string&) {});
  return runner.learn();
}

TEST(Runner, LearnsTheToyTaskAndWritesTheRunDirectory) {
  ToyEnv env(32);
  const std::string dir = runDir("learn");
  const TrainingSummary s = train(env, dir, 40);
  EXPECT_FALSE(s.interrupted);
  EXPECT_TRUE(s.error.empty()) << s.error;
  EXPECT_EQ(s.iterations, 40);
  EXPECT_EQ(s.env_steps, 40 * 16 * 32);
  const auto rows = readCsv(dir + "/progress.csv");
  ASSERT_EQ(rows.size(), 41u);
  const std::string header =
      "iteration,env_steps,mean_reward_per_step,mean_episode_return,"
      "env_steps_per_s,elapsed_s";
  std::string first_columns;
  for (int i = 0; i < 6; ++i) first_columns += (i ? "," : "") + rows[0][i];
  EXPECT_EQ(first_columns, header);
  const double first = std::stod(rows[1][2]), last = std::stod(rows.back()[2]);
  EXPECT_LT(first, 0.3) << "random policy";
  EXPECT_GT(last, 0.5) << "trained policy (max 0.6)";
  EXPECT_NEAR(s.final_reward, last, 1e-6);
  EXPECT_TRUE(std::filesystem::exists(dir + "/checkpoints/latest.pt"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/checkpoints/best.pt"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/config.yaml"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/summary.yaml"));
  EXPECT_EQ(readCheckpointMeta(dir + "/checkpoints/latest.pt").iteration, 40);
}

TEST(Runner, BestByLastMakesTheLastIterationTheBest) {
  // 5 iterations, saves every 2: best.pt is the last iteration's, written with latest.pt.
  ToyEnv env(8);
  const std::string dir = runDir("best_last");
  const TrainingSummary s = train(env, dir, 5, "", BestBy::kLast);
  EXPECT_TRUE(s.error.empty()) << s.error;
  EXPECT_EQ(readCheckpointMeta(dir + "/checkpoints/best.pt").iteration, 5);
  EXPECT_EQ(readCheckpointMeta(dir + "/checkpoints/latest.pt").iteration, 5);
  EXPECT_TRUE(std::filesystem::exists(dir + "/exported/policy.pt"));
}

/// Every CSV column but the timing ones.
std::vector<std::vector<std::string>> learningColumns(const std::string& path) {
  auto rows = readCsv(path);
  const std::vector<std::string> timing{"env_steps_per_s", "elapsed_s", "collection_s", "update_s"};
  std::vector<std::size_t> keep;
  for (std::size_t c = 0; c < rows[0].size(); ++c) {
    if (std::find(timing.begin(), timing.end(), rows[0][c]) == timing.end()) keep.push_back(c);
  }
  for (auto& row : rows) {
    std::vector<std::string> kept;
    for (std::size_t c : keep) kept.push_back(row.at(c));
    row = kept;
  }
  return rows;
}

TEST(Runner, TheCooldownBringsTheLearningRateDownToItsFloorAtTheLastIteration) {
  // A fixed rate of 1e-3 with lr_cooldown 0.5 of 8 iterations: iterations 1-4 learn at 1e-3,
  // 5-8 at the falling ceiling, the last at min_learning_rate.
  ToyEnv env(8);
  RunnerOptions o;
  o.iterations = 8;
  o.run_dir = runDir("cooldown");
  PpoConfig c = toyConfig();
  c.schedule = LrSchedule::kFixed;
  c.learning_rate = 1e-3;
  c.min_learning_rate = 1e-5;
  c.lr_cooldown = 0.5;
  OnPolicyRunner runner(env, c, o);
  runner.setLogger([](const std::string&) {});
  EXPECT_TRUE(runner.learn().error.empty());
  const auto rows = readCsv(o.run_dir + "/progress.csv");
  ASSERT_EQ(rows.size(), 9u);
  const auto column = std::find(rows[0].begin(), rows[0].end(), "learning_rate") - rows[0].begin();
  ASSERT_LT(column, static_cast<long>(rows[0].size()));
  const auto rate = [&](int iteration) { return std::stod(rows[iteration][column]); };
  for (int i = 1; i <= 4; ++i) EXPECT_NEAR(rate(i), 1e-3, 1e-12) << "iteration " << i;
  for (int i = 5; i <= 8; ++i) {
    EXPECT_NEAR(rate(i), 1e-5 + (1e-3 - 1e-5) * (8 - i) / 4.0, 1e-9) << "iteration " << i;
  }
  EXPECT_NEAR(rate(8), 1e-5, 1e-12);
}

TEST(Runner, SameSeedSameLearningCurve) {
  ToyEnv env_a(8), env_b(8);
  const std::string a = runDir("seed_a"), b = runDir("seed_b");
  train(env_a, a, 6);
  train(env_b, b, 6);
  const auto rows_a = learningColumns(a + "/progress.csv");
  EXPECT_EQ(rows_a.size(), 7u);
  EXPECT_EQ(rows_a, learningColumns(b + "/progress.csv"));

  // A different seed gives a different curve (the comparison can fail).
  ToyEnv env_c(8);
  const std::string c = runDir("seed_c");
  RunnerOptions o;
  o.iterations = 6;
  o.run_dir = c;
  PpoConfig other = toyConfig();
  other.seed = 4;
  OnPolicyRunner runner(env_c, other, o);
  runner.setLogger([](const std::string&) {});
  runner.learn();
  EXPECT_NE(rows_a, learningColumns(c + "/progress.csv"));
}

TEST(Runner, InterruptSavesTheLastCompletedIterationAndResumeContinues) {
  // 8 envs x 16 steps per iteration: interrupted during the 4th rollout (env step 50).
  ToyEnv env(8, /*interrupt_at=*/50);
  const std::string dir = runDir("interrupt");
  const TrainingSummary s = train(env, dir, 10);
  EXPECT_TRUE(s.interrupted);
  EXPECT_EQ(s.iterations, 3);
  const CheckpointMeta meta = readCheckpointMeta(dir + "/checkpoints/latest.pt");
  EXPECT_EQ(meta.iteration, 3);
  EXPECT_EQ(meta.env_steps, 3 * 16 * 8);

  ToyEnv again(8);
  const TrainingSummary r = train(again, dir, 5, dir + "/checkpoints/latest.pt");
  EXPECT_FALSE(r.interrupted);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_EQ(r.env_steps, 5 * 16 * 8);
  const auto rows = readCsv(dir + "/progress.csv");
  ASSERT_EQ(rows.size(), 6u);
  for (int i = 1; i <= 5; ++i) EXPECT_EQ(rows[i][0], std::to_string(i));
}

TEST(Runner, StaggersTheFirstEpisodesOnceAtTheStart) {
  // 8 envs, time-out at episode step 20: env i starts at episode step i x 20 / 8, so its first
  // episode ends after 20 - start steps, then every 20 steps; nothing is reset mid-rollout.
  ToyEnv env(8);
  train(env, runDir("stagger"), 3);
  const std::vector<std::uint32_t> starts{0, 2, 5, 7, 10, 12, 15, 17};
  EXPECT_EQ(env.starts, starts);
  EXPECT_EQ(staggeredStarts(8, 21), starts);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> first_ends;
  std::vector<bool> seen(8, false);
  for (const auto& [step, id] : env.ends) {
    if (!seen[id]) first_ends.emplace_back(step, id);
    seen[id] = true;
  }
  std::sort(first_ends.begin(), first_ends.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  for (const auto& [step, id] : first_ends) EXPECT_EQ(step, 20u - starts[id]) << "env " << id;

  ToyEnv plain(8);
  RunnerOptions o;
  o.iterations = 2;
  o.run_dir = runDir("no_stagger");
  PpoConfig c = toyConfig();
  c.stagger_episodes = false;
  OnPolicyRunner runner(plain, c, o);
  runner.setLogger([](const std::string&) {});
  runner.learn();
  EXPECT_TRUE(plain.starts.empty());
  for (const auto& [step, id] : plain.ends) EXPECT_EQ(step % 20, 0u) << "env " << id;
}

TEST(Runner, WritesObservationMeansOfLateEpisodeSteps) {
  // 4 envs, episodes of 20 steps (observations at episode steps 0..19), no staggering: samples
  // at episode step >= 10 per env: rollout 1 (global steps 0..15) episode steps 10..15 = 6;
  // rollout 2 (16..31) 16..19 and 10..11 = 6; rollout 3 (32..47) 12..19 = 8.
  ToyEnv env(4);
  env.setObservationNames({"v", "w", "zero"});
  RunnerOptions o;
  o.iterations = 3;
  o.run_dir = runDir("obs_means");
  PpoConfig c = toyConfig();
  c.stagger_episodes = false;
  OnPolicyRunner runner(env, c, o);  // obs_stats_from_step -1: 21 / 2 = 10
  runner.setLogger([](const std::string&) {});
  std::vector<IterationStats> stats;
  runner.setIterationCallback([&stats](const IterationStats& s) { stats.push_back(s); });
  runner.learn();
  const auto rows = readCsv(o.run_dir + "/progress.csv");
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> tail(rows[0].end() - 4, rows[0].end());
  EXPECT_EQ(tail,
            (std::vector<std::string>{"obs_samples", "obs_mean_v", "obs_mean_w", "obs_mean_zero"}));
  ASSERT_EQ(stats.size(), 3u);
  const std::int64_t expected[] = {4 * 6, 4 * 6, 4 * 8};
  for (std::size_t k = 0; k < stats.size(); ++k) {
    const IterationStats& s = stats[k];
    EXPECT_EQ(s.obs_samples, expected[k]);
    ASSERT_EQ(s.obs_means.size(), 3u);
    EXPECT_TRUE(std::isfinite(s.obs_means[0]));
    EXPECT_NE(s.obs_means[0], 0.0);
    EXPECT_EQ(s.obs_means[2], 0.0);
  }
  EXPECT_EQ(rows[1][rows[0].size() - 4], "24");

  // Unnamed observations get obs<k> columns; a start step beyond the episode is rejected.
  ToyEnv unnamed(2);
  o.iterations = 1;
  o.run_dir = runDir("obs_unnamed");
  o.obs_stats_from_step = 0;
  OnPolicyRunner plain(unnamed, c, o);
  plain.setLogger([](const std::string&) {});
  plain.setIterationCallback([](const IterationStats& s) { EXPECT_EQ(s.obs_samples, 2 * 16); });
  plain.learn();
  EXPECT_EQ(readCsv(o.run_dir + "/progress.csv")[0].back(), "obs_mean_obs2");
  o.obs_stats_from_step = 21;
  EXPECT_THROW(OnPolicyRunner(unnamed, c, o), ConfigError);
}

TEST(Runner, RejectsMoreMinibatchesThanSamples) {
  ToyEnv env(2);
  RunnerOptions o;
  o.run_dir = runDir("bad");
  PpoConfig c = toyConfig();
  c.num_steps_per_env = 2;
  c.num_mini_batches = 5;
  EXPECT_THROW(OnPolicyRunner(env, c, o), ConfigError);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
