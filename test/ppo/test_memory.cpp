// Policies with memory: the history's stacking and reset, recurrent states started over per env
// at episode ends, recurrent minibatches that recompute what acting computed, time-outs
// bootstrapped from the remembered state, and the TorchScript export of each kind.
#include <gtest/gtest.h>
#include <torch/script.h>

#include <filesystem>
#include <fstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/input_history.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

constexpr int kObsDim = 3, kActDim = 2, kNumEnvs = 4, kNumSteps = 10;

BatchSpec spec() {
  BatchSpec s;
  s.num_envs = kNumEnvs;
  s.obs_dim = kObsDim;
  s.action_dim = kActDim;
  s.action_low = {-20.0f, -20.0f};
  s.action_high = {20.0f, 20.0f};
  s.control_dt = 1.0 / 60.0;
  s.max_episode_length = 300;
  s.task = "command";
  s.observation_names = {"a", "b", "c"};
  s.action_names = {"left", "right"};
  return s;
}

PpoConfig memoryConfig(RnnType rnn, int obs_history, int action_history) {
  PpoConfig c;
  c.actor_hidden_dims = {8};
  c.critic_hidden_dims = {8};
  c.num_steps_per_env = kNumSteps;
  c.num_mini_batches = 2;
  c.num_learning_epochs = 1;
  c.rnn_type = rnn;
  c.rnn_hidden_size = 6;
  c.rnn_num_layers = 2;
  c.obs_history_length = obs_history;
  c.action_history_length = action_history;
  return c;
}

torch::Tensor identity(const torch::Tensor& x) { return x; }

std::vector<float> floats(const torch::Tensor& t) {
  const torch::Tensor c = t.contiguous();
  return std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
}

/// A step's answer for every env: random observations and rewards; `ended` envs end (time-outs
/// when `truncated`), with random final observations.
StepResult answer(std::uint64_t step, const std::vector<std::uint32_t>& ended, bool truncated) {
  StepResult r;
  r.step = step;
  r.observations = floats(torch::randn({kNumEnvs, kObsDim}));
  r.rewards = floats(torch::randn({kNumEnvs}));
  r.terminated.assign(kNumEnvs, 0);
  r.truncated.assign(kNumEnvs, 0);
  r.episode_steps.assign(kNumEnvs, 0);
  for (std::uint32_t e : ended) {
    (truncated ? r.truncated : r.terminated)[e] = 1;
    r.reset_env_ids.push_back(e);
    const std::vector<float> final_obs = floats(torch::randn({kObsDim}));
    r.final_observations.insert(r.final_observations.end(), final_obs.begin(), final_obs.end());
  }
  return r;
}

/// A rollout with episode ends at some steps (env 1 at step 3, envs 0 and 2 at step 6).
void rollout(Ppo& ppo) {
  StepResult r = answer(0, {}, false);
  for (int t = 0; t < kNumSteps; ++t) {
    ppo.act(r);
    std::vector<std::uint32_t> ended;
    if (t == 3) ended = {1};
    if (t == 6) ended = {0, 2};
    r = answer(t + 1, ended, t == 6);
    ppo.processEnvStep(r);
  }
  ppo.computeReturns(r);
}

TEST(InputHistory, StacksTheNewestFirstAndStartsOverWithTheFirstObservation) {
  InputHistory history(2, 2, 1, 3, 2);
  EXPECT_EQ(history.inputDim(), 3 * 2 + 2 * 1);
  const torch::Tensor all = torch::ones({2}, torch::kBool), none = torch::zeros({2}, torch::kBool);
  // An episode start: every observation slot holds the first observation, the actions are 0.
  torch::Tensor in = history.push(torch::tensor({{1.0f, 2.0f}, {3.0f, 4.0f}}), all, identity);
  EXPECT_TRUE(torch::equal(in[0], torch::tensor({1.0f, 2.0f, 1.0f, 2.0f, 1.0f, 2.0f, 0.0f, 0.0f})));
  history.pushActions(torch::tensor({{0.5f}, {-0.5f}}));
  in = history.push(torch::tensor({{5.0f, 6.0f}, {7.0f, 8.0f}}), none, identity);
  EXPECT_TRUE(torch::equal(in[0], torch::tensor({5.0f, 6.0f, 1.0f, 2.0f, 1.0f, 2.0f, 0.5f, 0.0f})));
  EXPECT_TRUE(
      torch::equal(in[1], torch::tensor({7.0f, 8.0f, 3.0f, 4.0f, 3.0f, 4.0f, -0.5f, 0.0f})));
  history.pushActions(torch::tensor({{0.25f}, {1.0f}}));
  // peek: what env 1 would see next, without a change; then env 1 starts over, env 0 goes on.
  const torch::Tensor peeked =
      history.peek(torch::tensor({1}, torch::kLong), torch::tensor({{9.0f, 9.0f}}),
                   torch::zeros({1}, torch::kBool), identity);
  EXPECT_TRUE(
      torch::equal(peeked[0], torch::tensor({9.0f, 9.0f, 7.0f, 8.0f, 3.0f, 4.0f, 1.0f, -0.5f})));
  in = history.push(torch::tensor({{10.0f, 11.0f}, {12.0f, 13.0f}}), torch::tensor({false, true}),
                    identity);
  EXPECT_TRUE(
      torch::equal(in[0], torch::tensor({10.0f, 11.0f, 5.0f, 6.0f, 1.0f, 2.0f, 0.25f, 0.5f})));
  EXPECT_TRUE(
      torch::equal(in[1], torch::tensor({12.0f, 13.0f, 12.0f, 13.0f, 12.0f, 13.0f, 0.0f, 0.0f})));
  // The observations go through the normaliser given, each slot alike.
  in = history.push(torch::tensor({{1.0f, 1.0f}, {1.0f, 1.0f}}), all,
                    [](const torch::Tensor& x) { return 2.0 * x; });
  EXPECT_TRUE(torch::equal(in[0].slice(0, 0, 6), torch::full({6}, 2.0f)));
}

class RecurrentTest : public testing::TestWithParam<RnnType> {};

TEST_P(RecurrentTest, TheStateStartsOverForExactlyTheEnvsThatEnded) {
  torch::manual_seed(3);
  PpoConfig c = memoryConfig(GetParam(), 1, 0);
  c.normalize_observations = false;  // the input is the observation
  Ppo ppo(spec(), c);
  StepResult r = answer(0, {}, false);
  for (int t = 0; t < 3; ++t) {
    ppo.act(r);
    r = answer(t + 1, t == 2 ? std::vector<std::uint32_t>{1} : std::vector<std::uint32_t>{}, false);
    ppo.processEnvStep(r);
  }
  const MemoryState before = ppo.memoryState();
  ppo.act(r);
  const MemoryState after = ppo.memoryState();
  // Expected: one step of the actor's RNN from the state before (env 1: from zeros).
  const torch::Tensor obs = torch::tensor(r.observations).reshape({kNumEnvs, kObsDim});
  torch::Tensor state = before.actor.clone();
  state[1].zero_();
  ppo.model()->actorMemory()->step(obs, state);
  EXPECT_TRUE(torch::allclose(after.actor, state, 0.0, 1e-6));
  EXPECT_FALSE(torch::allclose(before.actor[0], torch::zeros_like(before.actor[0])));
  // And env 1's state is what a fresh env computes from its observation alone.
  torch::Tensor fresh = torch::zeros({1, state.size(1)});
  ppo.model()->actorMemory()->step(obs.slice(0, 1, 2), fresh);
  EXPECT_TRUE(torch::allclose(after.actor[1], fresh[0], 0.0, 1e-6));
}

TEST_P(RecurrentTest, MiniBatchSequencesRecomputeWhatActingComputed) {
  torch::manual_seed(5);
  Ppo ppo(spec(), memoryConfig(GetParam(), 2, 1));
  rollout(ppo);
  int batches = 0;
  for (const MiniBatch& b : ppo.storage().sequenceMiniBatches(2)) {
    torch::NoGradGuard no_grad;
    ASSERT_EQ(b.obs.size(0), kNumSteps);
    ASSERT_EQ(b.obs.size(1), kNumEnvs / 2);
    const ActionEvaluation e = ppo.model()->evaluateSequence(b.obs, b.actions, b.state, b.starts);
    EXPECT_TRUE(torch::allclose(e.mean, b.old_mean, 0.0, 1e-6));
    EXPECT_TRUE(torch::allclose(e.values, b.old_values, 0.0, 1e-6));
    // Without the episode starts the states would run on through the ends: other outputs.
    const ActionEvaluation no_starts =
        ppo.model()->evaluateSequence(b.obs, b.actions, b.state, torch::zeros_like(b.starts));
    EXPECT_FALSE(torch::allclose(no_starts.mean, b.old_mean, 0.0, 1e-6));
    ++batches;
  }
  EXPECT_EQ(batches, 2);
  // The update learns from them (the parameters move).
  const torch::Tensor before = ppo.model()->actorMemory()->layers()[0].w_hh.clone();
  ppo.update();
  EXPECT_FALSE(torch::equal(before, ppo.model()->actorMemory()->layers()[0].w_hh));
}

TEST_P(RecurrentTest, ATimeOutBootstrapsFromTheRememberedState) {
  // Learner A sees env 0 time out after step 2 with final observation o; learner B (the same
  // seed) sees o as env 0's next observation instead. A's V(final observation) must be the value
  // B computes when it acts on o: the same history, the same recurrent state.
  PpoConfig c = memoryConfig(GetParam(), 3, 2);
  c.normalize_observations = false;
  std::vector<StepResult> answers;
  torch::manual_seed(8);
  for (int t = 0; t < 4; ++t) answers.push_back(answer(t, {}, false));
  StepResult timeout = answer(3, {0}, true);
  StepResult continued = answer(3, {}, false);
  std::copy(timeout.final_observations.begin(), timeout.final_observations.end(),
            continued.observations.begin());
  torch::manual_seed(1);
  Ppo a(spec(), c);
  torch::manual_seed(1);
  Ppo b(spec(), c);
  // Both sample the same actions (the global generator reseeded before each act).
  for (int t = 0; t < 2; ++t) {
    for (Ppo* p : {&a, &b}) {
      torch::manual_seed(100 + t);
      p->act(answers[t]);
      p->processEnvStep(answers[t + 1]);
    }
  }
  torch::manual_seed(102);
  a.act(answers[2]);
  a.processEnvStep(timeout);
  torch::manual_seed(102);
  b.act(answers[2]);
  b.processEnvStep(continued);
  b.act(continued);
  b.processEnvStep(answer(4, {}, false));  // stores the step's values
  const float bootstrap = a.storage().truncatedValues()[2][0].item<float>();
  EXPECT_NE(bootstrap, 0.0f);
  EXPECT_NEAR(bootstrap, b.storage().values()[3][0].item<float>(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(GruAndLstm, RecurrentTest, testing::Values(RnnType::kGru, RnnType::kLstm),
                         [](const testing::TestParamInfo<RnnType>& info) {
                           return enumName(info.param);
                         });

TEST(MemoryConfig, ARecurrentMinibatchHoldsWholeEnvSequences) {
  PpoConfig c = memoryConfig(RnnType::kGru, 1, 0);
  c.num_mini_batches = kNumEnvs + 1;
  try {
    Ppo ppo(spec(), c);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("num_mini_batches = 5"), std::string::npos) << e.what();
  }
  c.rnn_type = RnnType::kNone;  // shuffled samples: up to T x N minibatches
  EXPECT_NO_THROW(Ppo(spec(), c));
}

TEST(MemoryConfig, BadSettingsAreRefusedNamingTheField) {
  for (const auto& [yaml, field] : std::vector<std::pair<std::string, std::string>>{
           {"obs_history_length: 0", "obs_history_length = 0"},
           {"action_history_length: -1", "action_history_length = -1"},
           {"rnn_hidden_size: 0", "rnn_hidden_size = 0"},
           {"rnn_num_layers: 17", "rnn_num_layers = 17"}}) {
    const PpoConfig c = fromYaml(yaml);
    try {
      validate(c);
      FAIL() << yaml;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(fromYaml("rnn_type: transformer"), ConfigError);
}

/// Exported memory policies: the TorchScript module, fed its own hidden state back, gives the
/// checkpoint's actions over a sequence with an env starting over in the middle.
class ExportTest : public testing::TestWithParam<std::tuple<RnnType, int, int>> {};

TEST_P(ExportTest, TheTorchScriptPolicyActsAsTheCheckpointStepAfterStep) {
  const auto [rnn, obs_history, action_history] = GetParam();
  torch::manual_seed(2);
  const PpoConfig c = memoryConfig(rnn, obs_history, action_history);
  Ppo ppo(spec(), c);
  rollout(ppo);  // the normaliser learns something
  CheckpointMeta meta;
  meta.obs_dim = kObsDim;
  meta.action_dim = kActDim;
  meta.config = c;
  meta.spec = spec();
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_memory";
  std::filesystem::create_directories(dir);
  const std::string checkpoint = (dir / ("memory_" + enumName(rnn) + ".pt")).string();
  saveCheckpoint(checkpoint, ppo, meta);

  Policy policy(checkpoint);  // the action limits are the checkpoint's
  ASSERT_TRUE(policy.hasMemory());
  const std::string exported = (dir / "exported.pt").string();
  policy.exportTorchScript(exported, spec());
  torch::jit::Module module = torch::jit::load(exported);
  torch::Tensor hidden = module.run_method("initial_hidden", 3).toTensor();
  EXPECT_TRUE(torch::equal(hidden, torch::zeros_like(hidden)));

  torch::manual_seed(6);
  std::vector<torch::Tensor> outputs;
  bool moved = false;
  for (int t = 0; t < 12; ++t) {
    const torch::Tensor obs = 2.0 * torch::randn({3, kObsDim});
    if (t == 5) {  // env 2 starts over
      policy.resetMemory({2});
      hidden[2].zero_();
    }
    std::vector<float> expected;
    policy.act(floats(obs), 3, expected);
    const auto out = module.forward({obs, hidden}).toTuple();
    const torch::Tensor actions = out->elements()[0].toTensor();
    hidden = out->elements()[1].toTensor();
    EXPECT_TRUE(torch::allclose(actions.reshape({-1}), torch::tensor(expected), 0.0, 1e-5))
        << "step " << t << ": " << actions << " vs " << torch::tensor(expected);
    if (t > 0 && !torch::allclose(actions, outputs.back())) moved = true;
    outputs.push_back(actions);
  }
  EXPECT_TRUE(moved);
  // The memory matters: the same observation after different pasts gives different actions.
  std::vector<float> a, b;
  const std::vector<float> same = floats(torch::ones({3, kObsDim}));
  policy.resetMemory();
  policy.act(same, 3, a);
  policy.act(same, 3, b);
  EXPECT_NE(a, b);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ExportTest,
                         testing::Values(std::make_tuple(RnnType::kGru, 1, 0),
                                         std::make_tuple(RnnType::kLstm, 1, 0),
                                         std::make_tuple(RnnType::kNone, 3, 2),
                                         std::make_tuple(RnnType::kGru, 2, 1)),
                         [](const testing::TestParamInfo<std::tuple<RnnType, int, int>>& info) {
                           return enumName(std::get<0>(info.param)) + "_obs" +
                                  std::to_string(std::get<1>(info.param)) + "_actions" +
                                  std::to_string(std::get<2>(info.param));
                         });

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
