// The training figures: a round's wait (robots_per_env with rounds, outcome 5) is no episode,
// so it moves neither the outcome rates nor the returns.
#include <gtest/gtest.h>

#include <filesystem>

#include "jetbot_rl/ppo/iteration_stats.h"
#include "jetbot_rl/ppo/training_logger.h"
#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {
namespace ppo {
namespace {

StepResult ended(const std::vector<float>& rewards, const std::vector<std::uint32_t>& ids,
                 const std::vector<Outcome>& outcomes) {
  StepResult r;
  r.rewards = rewards;
  r.reset_env_ids = ids;
  for (Outcome o : outcomes) r.outcomes.push_back(static_cast<std::uint8_t>(o));
  return r;
}

TEST(TrainingLogger, ARoundsWaitIsNoEpisode) {
  LoggerOptions options;
  options.csv_path =
      (std::filesystem::temp_directory_path() / "jetbot_rl_test_logger_progress.csv").string();
  TrainingSummary summary;
  TrainingLogger logger(3, options, summary);
  logger.setSink([](const std::string&) {});
  // Row 0 reaches its goal (+10), row 1 hits a robot (-5); row 2 waited for its round.
  logger.recordStep(
      ended({10.0f, -5.0f, 0.0f}, {0, 1}, {Outcome::kSuccess, Outcome::kCollisionRobot}));
  logger.recordStep(ended({0.0f, 0.0f, 0.0f}, {2}, {Outcome::kWaited}));
  IterationStats s;
  s.iteration = s.iterations = 1;
  logger.endIteration(s);
  EXPECT_EQ(s.episodes, 2);
  EXPECT_DOUBLE_EQ(s.success_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.collision_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.timeout_rate, 0.0);
  EXPECT_DOUBLE_EQ(s.mean_episode_return, 2.5);
  std::filesystem::remove(options.csv_path);
}

/// Whether the second of two iterations is the best so far by `best_by`: the first has the
/// higher reward per step, the second ends the better episode.
bool secondIsBest(BestBy best_by) {
  LoggerOptions options;
  options.csv_path =
      (std::filesystem::temp_directory_path() / "jetbot_rl_test_logger_best.csv").string();
  options.best_by = best_by;
  TrainingSummary summary;
  TrainingLogger logger(2, options, summary);
  logger.setSink([](const std::string&) {});
  IterationStats s;
  s.iterations = 2;
  // Iteration 1: row 0 ends an episode of return 1, row 1 collects 9 so far.
  logger.recordStep(ended({1.0f, 9.0f}, {0}, {Outcome::kSuccess}));
  s.iteration = 1;
  EXPECT_TRUE(logger.endIteration(s));
  // Iteration 2: row 1's episode ends with return 2, row 0's next one with 5.
  logger.recordStep(ended({1.0f, -7.0f}, {1}, {Outcome::kCollision}));
  logger.recordStep(ended({4.0f, 0.0f}, {0}, {Outcome::kSuccess}));
  s.iteration = 2;
  const bool best = logger.endIteration(s);
  std::filesystem::remove(options.csv_path);
  return best;
}

TEST(TrainingLogger, BestByRewardPerStepByEpisodeReturnOrTheLast) {
  // Reward per step: 5, then -0.5; mean return of the episodes: 1, then (1 + 2 + 5) / 3.
  EXPECT_FALSE(secondIsBest(BestBy::kRewardPerStep));
  EXPECT_TRUE(secondIsBest(BestBy::kEpisodeReturn));
  EXPECT_TRUE(secondIsBest(BestBy::kLast));  // whatever its reward
  TrainingSummary summary;
  summary.best_by = BestBy::kLast;
  EXPECT_NE(describeSummary(summary).find("\nlast_mean_reward_per_step: "), std::string::npos)
      << describeSummary(summary);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
