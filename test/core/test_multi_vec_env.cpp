// MultiVecEnv: several batches as one, in list order, bit for bit what each part gives alone with
// its derived seed; parts whose specs disagree are refused naming the part and the field.
#include <gtest/gtest.h>

#include "jetbot_rl/env/local_vec_env.h"
#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/tasks/task_factory.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

std::unique_ptr<VecEnv> part(int num_envs, TaskKind task = TaskKind::kCommand) {
  TaskConfig t;
  t.task = task;
  return std::make_unique<LocalVecEnv>(
      std::make_unique<BatchedEnv>(test::jetbot(), test::smallConfig(num_envs), makeTask(t)));
}

template <typename T>
std::vector<T> cat(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

TEST(MultiVecEnv, IsTheConcatenationOfItsPartsWithDerivedSeeds) {
  std::vector<std::unique_ptr<VecEnv>> list;
  list.push_back(part(3));
  list.push_back(part(2));
  MultiVecEnv multi(std::move(list), {"/a", "/b"});
  auto a = part(3), b = part(2);
  EXPECT_EQ(multi.spec().num_envs, 5);
  EXPECT_EQ(MultiVecEnv::partSeed(7, 0), 7);
  EXPECT_EQ(MultiVecEnv::partSeed(7, 1), 7 + (std::int64_t{1} << 32));
  EXPECT_EQ(MultiVecEnv::partSeed(-1, 1), -1);

  const std::vector<std::uint32_t> starts{0, 100, 200, 50, 297};
  const StepResult& m0 = multi.reset(7, starts);
  const StepResult& a0 = a->reset(7, {0, 100, 200});
  const StepResult& b0 = b->reset(7 + (std::int64_t{1} << 32), {50, 297});
  EXPECT_TRUE(test::bitEqual(m0.observations, cat(a0.observations, b0.observations)));
  EXPECT_EQ(m0.episode_steps, cat(a0.episode_steps, b0.episode_steps));

  bool saw_reset_in_b = false;
  for (int s = 0; s < 40; ++s) {
    const std::vector<float> actions = test::randomActions(5, s);
    const StepResult& m = multi.step(actions);
    const StepResult& ra = a->step(std::vector<float>(actions.begin(), actions.begin() + 6));
    const StepResult& rb = b->step(std::vector<float>(actions.begin() + 6, actions.end()));
    ASSERT_TRUE(test::bitEqual(m.observations, cat(ra.observations, rb.observations))) << s;
    ASSERT_TRUE(test::bitEqual(m.rewards, cat(ra.rewards, rb.rewards))) << s;
    ASSERT_EQ(m.truncated, cat(ra.truncated, rb.truncated)) << s;
    ASSERT_EQ(m.episode_steps, cat(ra.episode_steps, rb.episode_steps)) << s;
    std::vector<std::uint32_t> ids = ra.reset_env_ids;
    for (std::uint32_t id : rb.reset_env_ids) ids.push_back(id + 3);
    ASSERT_EQ(m.reset_env_ids, ids) << s;
    ASSERT_TRUE(
        test::bitEqual(m.final_observations, cat(ra.final_observations, rb.final_observations)));
    saw_reset_in_b = saw_reset_in_b || !rb.reset_env_ids.empty();
  }
  EXPECT_TRUE(saw_reset_in_b) << "env 4 started at episode step 297: it must have timed out";
  EXPECT_THROW(multi.stepAsync(std::vector<float>(9, 0.0f)), InputError);
}

TEST(MultiVecEnv, PartsThatDisagreeAreRefusedNamingThePartAndTheField) {
  std::vector<std::unique_ptr<VecEnv>> list;
  list.push_back(part(2, TaskKind::kVelocity));
  list.push_back(part(2, TaskKind::kCommand));
  try {
    MultiVecEnv multi(std::move(list), {"/a", "/b"});
    FAIL() << "accepted parts of different tasks";
  } catch (const ConfigError& e) {
    // Every field that differs is named: the task, the observation names (both tasks observe 3
    // values) and their bounds.
    const std::string what = e.what();
    EXPECT_NE(what.find("env /b differs from env /a: "), std::string::npos) << what;
    EXPECT_NE(what.find("task: command differs from velocity"), std::string::npos) << what;
    EXPECT_NE(what.find("observation_names: [forward_dot_command"), std::string::npos) << what;
    EXPECT_NE(what.find("observation_low: [-1, -1, -.inf] differs from [-.inf, -.inf, -.inf]"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace jetbot_rl
