// The pieces of the PPO update, each against hand-computed values: the clipped surrogate and
// value loss (and where their gradients vanish), the adaptive learning rate and its cooldown, the
// observation normaliser and the action scaler.
#include <gtest/gtest.h>

#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/action_scaler.h"
#include "jetbot_rl/ppo/obs_normalizer.h"
#include "jetbot_rl/ppo/ppo_losses.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// The surrogate of one sample and its gradient with respect to the ratio.
std::pair<double, double> surrogateAndGradient(double ratio, double advantage, double clip) {
  torch::Tensor r = torch::tensor({ratio}, torch::kDouble).requires_grad_(true);
  const torch::Tensor loss = clippedSurrogate(r, torch::tensor({advantage}, torch::kDouble), clip);
  loss.backward();
  return {loss.item<double>(), r.grad().item<double>()};
}

TEST(PpoLosses, TheSurrogateIsClippedOnlyWhereTheRatioMovedTheProfitableWay) {
  // A > 0: a ratio above 1 + clip earns no more (loss -1.2, no gradient); below 1 - clip it is
  // not clipped (the pessimistic bound keeps its gradient).
  auto [loss, grad] = surrogateAndGradient(1.5, 1.0, 0.2);
  EXPECT_DOUBLE_EQ(loss, -1.2);
  EXPECT_DOUBLE_EQ(grad, 0.0);
  std::tie(loss, grad) = surrogateAndGradient(0.5, 1.0, 0.2);
  EXPECT_DOUBLE_EQ(loss, -0.5);
  EXPECT_DOUBLE_EQ(grad, -1.0);
  // A < 0: the mirror image.
  std::tie(loss, grad) = surrogateAndGradient(0.5, -2.0, 0.2);
  EXPECT_DOUBLE_EQ(loss, 1.6);
  EXPECT_DOUBLE_EQ(grad, 0.0);
  std::tie(loss, grad) = surrogateAndGradient(1.5, -2.0, 0.2);
  EXPECT_DOUBLE_EQ(loss, 3.0);
  EXPECT_DOUBLE_EQ(grad, 2.0);
  // Inside the clip range: the plain -A r.
  std::tie(loss, grad) = surrogateAndGradient(1.1, 3.0, 0.2);
  EXPECT_NEAR(loss, -3.3, 1e-12);
  EXPECT_DOUBLE_EQ(grad, -3.0);
}

TEST(PpoLosses, TheClippedValueLossTakesTheLargerError) {
  const auto t = [](double v) { return torch::tensor({v}, torch::kDouble); };
  // The value moved 1.0 from 0 towards a return of 2: clipped to 0.2 its error is 1.8^2.
  EXPECT_NEAR(valueLoss(t(1.0), t(0.0), t(2.0), 0.2, true).item<double>(), 1.8 * 1.8, 1e-12);
  EXPECT_NEAR(valueLoss(t(1.0), t(0.0), t(2.0), 0.2, false).item<double>(), 1.0, 1e-12);
  // Moving away from the return: the unclipped error is the larger one.
  EXPECT_NEAR(valueLoss(t(-1.0), t(0.0), t(2.0), 0.2, true).item<double>(), 9.0, 1e-12);
}

TEST(PpoLosses, KlOfGaussians) {
  const auto t = [](double v) { return torch::tensor({{v}}, torch::kDouble); };
  EXPECT_NEAR(gaussianKl(t(0.0), t(1.0), t(0.0), t(1.0)), 0.0, 1e-12);
  // KL(N(0, 1) || N(1, 2)) = log 2 + (1 + 1) / 8 - 1/2.
  EXPECT_NEAR(gaussianKl(t(0.0), t(1.0), t(1.0), t(2.0)), std::log(2.0) + 0.25 - 0.5, 1e-12);
}

TEST(PpoLosses, TheAdaptiveLearningRateFollowsTheKl) {
  PpoConfig c;
  c.desired_kl = 0.01;
  c.min_learning_rate = 1e-4;
  c.max_learning_rate = 1e-2;
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1e-3, 0.05, c), 1e-3 / 1.5);  // KL too large
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1e-3, 0.001, c), 1.5e-3);     // KL small
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1e-3, 0.01, c), 1e-3);        // in the band
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1e-3, 0.0, c), 1e-3);         // no change at all
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1.2e-4, 0.05, c), 1e-4);      // bounded below
  EXPECT_DOUBLE_EQ(adaptedLearningRate(9e-3, 0.001, c), 1e-2);       // and above
  c.schedule = LrSchedule::kFixed;
  EXPECT_DOUBLE_EQ(adaptedLearningRate(1e-3, 0.05, c), 1e-3);
}

TEST(PpoLosses, TheCooldownLowersTheCeilingLinearlyOverTheLastIterations) {
  PpoConfig c;
  c.min_learning_rate = 1e-5;
  c.max_learning_rate = 5e-4;
  const double none = std::numeric_limits<double>::infinity();
  EXPECT_EQ(learningRateCeiling(c, 99, 100), none);  // lr_cooldown 0: never
  c.lr_cooldown = 0.25;                              // the last 25 of 100 iterations
  EXPECT_EQ(learningRateCeiling(c, 0, 100), none);
  EXPECT_EQ(learningRateCeiling(c, 74, 100), none);  // 25 iterations after it: still outside
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 75, 100), 1e-5 + (5e-4 - 1e-5) * 24.0 / 25.0);
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 87, 100), 1e-5 + (5e-4 - 1e-5) * 12.0 / 25.0);
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 99, 100), 1e-5);  // the last update: the floor
  c.schedule = LrSchedule::kFixed;                          // from the fixed rate instead
  c.learning_rate = 1e-3;
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 99, 100), 1e-5);
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 75, 100), 1e-5 + (1e-3 - 1e-5) * 24.0 / 25.0);
  c.lr_cooldown = 1.0;  // the whole run
  EXPECT_DOUBLE_EQ(learningRateCeiling(c, 0, 100), 1e-5 + (1e-3 - 1e-5) * 99.0 / 100.0);
}

TEST(ObsNormalizer, MatchesTheStatisticsOfEverythingSeenAndClips) {
  torch::manual_seed(3);
  ObsNormalizer normalizer(2, true);
  const torch::Tensor a = torch::randn({50, 2}) * 3.0 + 1.0;
  const torch::Tensor b = torch::randn({30, 2}) * 0.5 - 2.0;
  normalizer->update(a);
  normalizer->update(b);
  const torch::Tensor all = torch::cat({a, b}).to(torch::kDouble);
  EXPECT_TRUE(torch::allclose(normalizer->mean(), all.mean(0), 1e-9, 1e-9));
  EXPECT_TRUE(torch::allclose(normalizer->var(), all.var(0, /*unbiased=*/false), 1e-9, 1e-9));
  EXPECT_EQ(normalizer->count(), 80.0);
  const torch::Tensor x = torch::tensor({{0.0f, 1e6f}});
  const torch::Tensor n = normalizer->normalize(x);
  const double mean0 = normalizer->mean()[0].item<double>();
  const double std0 = std::sqrt(normalizer->var()[0].item<double>());
  EXPECT_NEAR(n[0][0].item<double>(), (0.0 - mean0) / (std0 + 0.01), 1e-5);
  EXPECT_FLOAT_EQ(n[0][1].item<float>(), 10.0f);  // clipped

  ObsNormalizer off(2, false);
  off->update(a);
  EXPECT_EQ(off->count(), 0.0);
  EXPECT_TRUE(torch::equal(off->normalize(x), x));
}

TEST(ActionScaler, MapsSquashedActionsOntoTheLimits) {
  const ActionScaler clip({-20.0f, 0.0f}, {20.0f, 10.0f}, ActionSquash::kClip);
  std::vector<float> out;
  clip.toEnv(torch::tensor({{-3.0f, 0.5f}, {0.25f, 2.0f}}), out);
  EXPECT_EQ(out, (std::vector<float>{-20.0f, 7.5f, 5.0f, 10.0f}));
  const ActionScaler tanh({-20.0f, 0.0f}, {20.0f, 10.0f}, ActionSquash::kTanh);
  tanh.toEnv(torch::tensor({{1.0f, 0.0f}}), out);
  EXPECT_NEAR(out[0], 20.0 * std::tanh(1.0), 1e-5);
  EXPECT_NEAR(out[1], 5.0, 1e-6);
  EXPECT_THROW(ActionScaler({1.0f}, {1.0f}, ActionSquash::kClip), ConfigError);
  EXPECT_THROW(ActionScaler({-1.0f, -1.0f}, {1.0f}, ActionSquash::kClip), ConfigError);
  EXPECT_THROW(ActionScaler({NAN}, {1.0f}, ActionSquash::kClip), ConfigError);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
