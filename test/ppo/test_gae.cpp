// GAE(lambda) and returns with time-out bootstrapping: hand-computed cases.
#include <gtest/gtest.h>

#include "jetbot_rl/ppo/gae.h"
#include "jetbot_rl/ppo/rollout_storage.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

constexpr double kGamma = 0.9, kLambda = 0.8;

torch::Tensor col(std::vector<float> v) {  // [T] -> [T, 1]
  return torch::tensor(v, torch::kFloat).unsqueeze(1);
}

void expectColumn(const torch::Tensor& x, int64_t env, std::vector<double> expected) {
  ASSERT_EQ(x.size(0), static_cast<int64_t>(expected.size()));
  for (std::size_t t = 0; t < expected.size(); ++t) {
    EXPECT_NEAR(x[t][env].item<double>(), expected[t], 1e-5) << "t = " << t << ", env " << env;
  }
}

// Three steps of reward 1 with V = 0.5 everywhere: delta = 1 + 0.9 * 0.5 - 0.5 = 0.95.
const torch::Tensor kRewards = col({1, 1, 1});
const torch::Tensor kValues = col({0.5, 0.5, 0.5});
const torch::Tensor kLast = torch::tensor({0.5f});

TEST(Gae, NoEpisodeEndBootstrapsWithTheNextValue) {
  const auto r = computeGae(kRewards, kValues, kLast, col({0, 0, 0}), col({0, 0, 0}),
                            col({99, 99, 99}), kGamma, kLambda);
  // A2 = 0.95; A1 = 0.95 + 0.72 * 0.95 = 1.634; A0 = 0.95 + 0.72 * 1.634 = 2.12648
  expectColumn(r.advantages, 0, {2.12648, 1.634, 0.95});
  expectColumn(r.returns, 0, {2.62648, 2.134, 1.45});
}

TEST(Gae, TruncatedStepBootstrapsWithTheValueOfTheFinalObservation) {
  // Time-out at t = 1 with V(final obs) = 2: delta1 = 1 + 0.9 * 2 - 0.5 = 2.3, and A2 (the next
  // episode) is not carried back: A1 = 2.3; A0 = 0.95 + 0.72 * 2.3 = 2.606.
  const auto r = computeGae(kRewards, kValues, kLast, col({0, 0, 0}), col({0, 1, 0}),
                            col({99, 2, 99}), kGamma, kLambda);
  expectColumn(r.advantages, 0, {2.606, 2.3, 0.95});
  expectColumn(r.returns, 0, {3.106, 2.8, 1.45});
}

TEST(Gae, TruncatedBootstrapIgnoresTheNextEpisodesValue) {
  // Same as above but the next episode's first value is wildly different: t = 1 must not see it.
  const auto r = computeGae(kRewards, col({0.5, 0.5, -100}), kLast, col({0, 0, 0}), col({0, 1, 0}),
                            col({99, 2, 99}), kGamma, kLambda);
  EXPECT_NEAR(r.advantages[1][0].item<double>(), 2.3, 1e-5);
  EXPECT_NEAR(r.advantages[0][0].item<double>(), 2.606, 1e-5);
}

TEST(Gae, TerminatedStepDoesNotBootstrap) {
  // Terminal at t = 1: delta1 = 1 - 0.5 = 0.5 = A1; A0 = 0.95 + 0.72 * 0.5 = 1.31. The value in
  // truncated_values (2) must be ignored, also when truncated is set together with terminated.
  for (float trunc : {0.0f, 1.0f}) {
    const auto r = computeGae(kRewards, kValues, kLast, col({0, 1, 0}), col({0, trunc, 0}),
                              col({99, 2, 99}), kGamma, kLambda);
    expectColumn(r.advantages, 0, {1.31, 0.5, 0.95});
  }
}

TEST(Gae, TruncationOnTheLastStepUsesTheFinalObservationNotLastValues) {
  const auto r = computeGae(kRewards, kValues, torch::tensor({-50.0f}), col({0, 0, 0}),
                            col({0, 0, 1}), col({99, 99, 2}), kGamma, kLambda);
  // delta2 = 1 + 1.8 - 0.5 = 2.3; A1 = 0.95 + 0.72 * 2.3 = 2.606; A0 = 0.95 + 0.72 * 2.606
  expectColumn(r.advantages, 0, {2.82632, 2.606, 2.3});
}

TEST(Gae, GammaAndLambdaOneGiveMonteCarloReturnsPlusBootstrap) {
  const auto r = computeGae(col({1, 2, 3}), col({7, -3, 4}), torch::tensor({10.0f}), col({0, 0, 0}),
                            col({0, 0, 0}), col({0, 0, 0}), 1.0, 1.0);
  expectColumn(r.returns, 0, {16, 15, 13});
}

TEST(Gae, EnvsAreIndependent) {
  // env 0: truncated at t = 1; env 1: terminated at t = 1; env 2: no end.
  const auto ones = torch::ones({3, 3});
  const auto r = computeGae(ones, 0.5 * ones, torch::full({3}, 0.5f),
                            col({0, 1, 0}).repeat({1, 3}) * torch::tensor({0.f, 1.f, 0.f}),
                            col({0, 1, 0}).repeat({1, 3}) * torch::tensor({1.f, 0.f, 0.f}),
                            2 * ones, kGamma, kLambda);
  expectColumn(r.advantages, 0, {2.606, 2.3, 0.95});
  expectColumn(r.advantages, 1, {1.31, 0.5, 0.95});
  expectColumn(r.advantages, 2, {2.12648, 1.634, 0.95});
}

TEST(RolloutStorage, ReturnsAndNormalisedAdvantages) {
  torch::manual_seed(0);
  RolloutStorage storage(3, 1, 2, 1);
  const float trunc[3] = {0, 1, 0};
  for (int t = 0; t < 3; ++t) {
    storage.add(t, torch::randn({1, 2}), torch::randn({1, 1}), torch::zeros({1}),
                torch::full({1}, 0.5f), torch::zeros({1, 1}), torch::ones({1, 1}), torch::ones({1}),
                torch::zeros({1}), torch::full({1}, trunc[t]), torch::full({1}, 2.0f));
  }
  storage.computeReturns(kLast, kGamma, kLambda);
  expectColumn(storage.rawAdvantages(), 0, {2.606, 2.3, 0.95});
  expectColumn(storage.returns(), 0, {3.106, 2.8, 1.45});
  const auto batches = storage.miniBatches(1);
  ASSERT_EQ(batches.size(), 1u);
  EXPECT_NEAR(batches[0].advantages.mean().item<double>(), 0.0, 1e-5);
  EXPECT_NEAR(batches[0].advantages.std().item<double>(), 1.0, 1e-5);
  EXPECT_EQ(batches[0].obs.sizes(), (std::vector<int64_t>{3, 2}));
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
