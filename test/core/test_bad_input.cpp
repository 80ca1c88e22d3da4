// Bad input is rejected with a message naming it, and changes nothing; diverged envs reset alone.
#include "jetbot_rl/errors.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

/// Expects `f` to throw InputError whose message contains every one of `parts`.
template <typename F>
void expectInputError(F f, std::initializer_list<const char*> parts) {
  try {
    f();
    FAIL() << "no InputError thrown";
  } catch (const InputError& e) {
    for (const char* p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
}

/// Two identical batches; `victim` receives the bad input, `control` never does.
struct Twins {
  BatchedEnv victim{jetbot(), smallConfig(3)};
  BatchedEnv control{jetbot(), smallConfig(3)};
  void stepBoth(int s) {
    victim.step(randomActions(3, s));
    control.step(randomActions(3, s));
  }
  void expectSame(int steps_after) {
    for (int s = 0; s < steps_after; ++s) {
      stepBoth(100 + s);
      ASSERT_TRUE(bitEqual(victim.state().observations, control.state().observations));
      ASSERT_EQ(victim.state().episode_steps, control.state().episode_steps);
    }
  }
};

TEST(BadInput, WrongSizedActionsAreRejectedAndStepNothing) {
  Twins t;
  for (int s = 0; s < 20; ++s) t.stepBoth(s);
  expectInputError([&] { t.victim.step(std::vector<float>(5, 1.0f)); }, {"expected 6", "got 5"});
  expectInputError([&] { t.victim.step(std::vector<float>(7, 1.0f)); }, {"got 7"});
  expectInputError([&] { t.victim.step(nullptr, 6); }, {"actions"});
  EXPECT_EQ(t.victim.state().episode_steps[0], 20u);
  t.expectSame(30);
}

TEST(BadInput, NonFiniteActionsNameTheEnvAndValue) {
  Twins t;
  for (int s = 0; s < 20; ++s) t.stepBoth(s);
  auto actions = randomActions(3, 999);
  actions[5] = std::nanf("");
  expectInputError([&] { t.victim.step(actions); }, {"env 2", "right_wheel_joint", "nan"});
  actions[5] = 0.0f;
  actions[0] = -INFINITY;
  expectInputError([&] { t.victim.step(actions); }, {"env 0", "left_wheel_joint", "inf"});
  t.expectSame(30);
}

TEST(BadInput, UnknownOrDuplicateResetIdsResetNothing) {
  Twins t;
  for (int s = 0; s < 20; ++s) t.stepBoth(s);
  expectInputError([&] { t.victim.reset({0, 3}); }, {"id 3", "out of range"});
  expectInputError([&] { t.victim.reset({1, 2, 1}); }, {"id 1", "twice"});
  EXPECT_EQ(t.victim.state().episode_steps, std::vector<uint32_t>(3, 20u));
  t.expectSame(30);
}

TEST(BadInput, InvalidRootStateIsRejected) {
  Twins t;
  RootState s = t.victim.view(0).rootState();
  s.com_linear_velocity.x() = std::nan("");
  expectInputError([&] { t.victim.setRootState(0, s); }, {"env 0", "finite"});
  expectInputError([&] { t.victim.setRootState(5, RootState()); }, {"env 5", "out of range"});
  t.expectSame(10);
}

TEST(BadInput, ADivergedEnvIsResetAloneAndReported) {
  Twins t;
  for (int s = 0; s < 20; ++s) t.stepBoth(s);
  RootState absurd = t.victim.view(1).rootState();
  absurd.com_linear_velocity = Eigen::Vector3d(1e6, 0, 0);
  t.victim.setRootState(1, absurd);
  const StepResult& r = t.victim.step(randomActions(3, 20));
  t.control.step(randomActions(3, 20));
  ASSERT_EQ(r.reset_env_ids, std::vector<uint32_t>{1});
  EXPECT_TRUE(r.truncated[1]);
  EXPECT_FALSE(r.truncated[0] || r.truncated[2]);
  ASSERT_EQ(r.divergences.size(), 1u);
  EXPECT_EQ(r.divergences[0].env, 1u);
  for (const char* part : {"env 1 diverged", "link 'base_link'", "limit"}) {
    EXPECT_NE(r.divergences[0].reason.find(part), std::string::npos) << r.divergences[0].reason;
  }
  EXPECT_EQ(t.victim.divergedCount(), 1u);
  EXPECT_EQ(r.rewards[1], 0.0f);
  for (float f : r.final_observations) EXPECT_TRUE(std::isfinite(f));
  EXPECT_EQ(r.episode_steps[1], 0u);
  for (int e : {0, 2}) EXPECT_TRUE(bitEqual(envObs(t.victim, e), envObs(t.control, e)));
}

}  // namespace
}  // namespace jetbot_rl
