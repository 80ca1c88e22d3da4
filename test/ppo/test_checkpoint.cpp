// Checkpoint round trips: same outputs after reload; normaliser, optimiser and metadata restored.
#include <gtest/gtest.h>
#include <torch/script.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unordered_map>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {
namespace {

constexpr int kObs = 3, kAct = 2, kSteps = 8, kEnvs = 4;

std::string tempPath(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_checkpoint";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

PpoConfig testConfig() {
  PpoConfig c;
  c.actor_hidden_dims = {16, 8};
  c.critic_hidden_dims = {12};
  c.activation = Activation::kTanh;
  c.num_steps_per_env = kSteps;
  c.num_mini_batches = 2;
  c.num_learning_epochs = 2;
  c.learning_rate = 3e-3;
  c.seed = 7;
  return c;
}

BatchSpec testSpec(int obs_dim = kObs) {
  BatchSpec spec;
  spec.num_envs = kEnvs;
  spec.obs_dim = obs_dim;
  spec.action_dim = kAct;
  spec.action_low.assign(kAct, -1.0f);
  spec.action_high.assign(kAct, 1.0f);
  spec.control_dt = 1.0 / 60.0;
  spec.max_episode_length = 300;
  return spec;
}

std::vector<float> randomFloats(int n, double scale, double offset) {
  const torch::Tensor t = scale * torch::randn({n}) + offset;
  return std::vector<float>(t.data_ptr<float>(), t.data_ptr<float>() + n);
}

/// Fills `ppo`'s rollout with random observations and rewards through act / processEnvStep and
/// computes its returns (deterministic for a given torch seed and model).
void randomRollout(Ppo& ppo) {
  StepResult r;
  r.terminated.assign(kEnvs, 0);
  r.truncated.assign(kEnvs, 0);
  r.episode_steps.assign(kEnvs, 0);
  r.observations = randomFloats(kEnvs * kObs, 3.0, 1.0);
  for (int t = 0; t < kSteps; ++t) {
    ppo.act(r);
    r.observations = randomFloats(kEnvs * kObs, 3.0, 1.0);
    r.rewards = randomFloats(kEnvs, 1.0, 0.5);
    ppo.processEnvStep(r);
  }
  ppo.computeReturns(r);
}

std::vector<torch::Tensor> parameters(Ppo& ppo) {
  std::vector<torch::Tensor> out;
  for (const auto& p : ppo.model()->parameters()) out.push_back(p.detach().clone());
  return out;
}

bool sameTensors(const std::vector<torch::Tensor>& a, const std::vector<torch::Tensor>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!torch::equal(a[i], b[i])) return false;
  }
  return true;
}

class CheckpointTest : public testing::Test {
 protected:
  void SetUp() override {
    torch::manual_seed(1);
    trained = std::make_unique<Ppo>(testSpec(), testConfig());
    for (int i = 0; i < 3; ++i) {
      randomRollout(*trained);
      trained->update();
    }
    meta.iteration = 42;
    meta.env_steps = 123456;
    meta.elapsed_s = 12.5;
    meta.best_reward = 0.55;
    meta.learning_rate = trained->learningRate();
    meta.obs_dim = kObs;
    meta.action_dim = kAct;
    meta.config = testConfig();
    path = tempPath("round_trip.pt");
    saveCheckpoint(path, *trained, meta);
  }

  std::unique_ptr<Ppo> trained;
  CheckpointMeta meta;
  std::string path;
};

TEST_F(CheckpointTest, MetadataRoundTrip) {
  const CheckpointMeta m = readCheckpointMeta(path);
  EXPECT_EQ(m.iteration, 42);
  EXPECT_EQ(m.env_steps, 123456);
  EXPECT_DOUBLE_EQ(m.elapsed_s, 12.5);
  EXPECT_DOUBLE_EQ(m.best_reward, 0.55);
  EXPECT_DOUBLE_EQ(m.learning_rate, trained->learningRate());
  EXPECT_EQ(m.obs_dim, kObs);
  EXPECT_EQ(m.action_dim, kAct);
  EXPECT_EQ(toYaml(readCheckpointConfig(path)), toYaml(testConfig()));
  EXPECT_EQ(networkYaml(m.config), networkYaml(testConfig()));
}

TEST_F(CheckpointTest, TheEnvsSpecWithItsObservationContractRoundTrips) {
  meta.spec = testSpec();
  meta.spec.task = "navigation";
  ObserverSpec& o = meta.spec.observer;
  o.scan_beam_angles = {-0.5, 0.1, 0.7};
  o.scan_range = {0.15, 3.5};
  o.scan_beam_width = 0.1;
  o.log_beams = true;
  o.goal_radius = 0.25;
  o.path_lookahead = 0.6;
  o.path_clearance = 0.35;
  o.path_clearance_cost = 2.5;
  o.wheel_radius = 0.03;
  o.wheel_separation = 0.1125;
  o.footprint_radius = 0.095;
  o.speed_limit_path = {0.06, 0.074, -0.074};
  o.speed_limit_distances = {0.1, 0.4};
  const std::string with_beams = tempPath("with_beams.pt");
  saveCheckpoint(with_beams, *trained, meta);
  const BatchSpec read = readCheckpointMeta(with_beams).spec;
  EXPECT_EQ(read.task, "navigation");
  EXPECT_EQ(fieldsToYaml(read.observer), fieldsToYaml(o));  // every field of the contract
  EXPECT_EQ(read.action_high, meta.spec.action_high);
  EXPECT_NO_THROW(requireObservationContract(readCheckpointMeta(with_beams), with_beams));
  // A task without a scan reads none.
  EXPECT_TRUE(readCheckpointMeta(path).spec.observer.scan_beam_angles.empty());
  // The export's meta.yaml carries them too.
  Policy policy(with_beams);
  const std::string exported = tempPath("exported_beams/policy.pt");
  policy.exportTorchScript(exported, meta.spec);
  std::unordered_map<std::string, std::string> extra{{"meta.yaml", ""}};
  torch::jit::load(exported, c10::nullopt, extra);
  EXPECT_NE(
      extra["meta.yaml"].find("\nscan_beam_angles: [-0.5, 0.1, 0.7]\nscan_range: [0.15, 3.5]\n"
                              "scan_beam_width: 0.1\nlog_beams: true\n"),
      std::string::npos)
      << extra["meta.yaml"];
}

TEST_F(CheckpointTest, AFileWrittenBeforeTheContractIsRefusedWhereTheContractIsNeeded) {
  EXPECT_EQ(readCheckpointMeta(path).format_version, kObservationContractFormat);
  CheckpointMeta old = readCheckpointMeta(path);
  old.format_version = 2;  // as read from a file of format 2
  try {
    requireObservationContract(old, "old.pt");
    FAIL() << "accepted a checkpoint without its observation contract";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint old.pt (format 2) was written before "
                                         "checkpoints held the observation contract"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("resume it for one iteration"), std::string::npos);
  }
}

TEST_F(CheckpointTest, SameOutputsAndNormaliserAfterReload) {
  torch::manual_seed(99);  // different initial weights: the load must overwrite them
  Ppo loaded(testSpec(), testConfig());
  const torch::Tensor obs = torch::randn({10, kObs});
  ASSERT_FALSE(torch::equal(loaded.model()->actionMean(obs), trained->model()->actionMean(obs)));

  loadCheckpoint(path, loaded);
  EXPECT_TRUE(torch::equal(loaded.model()->actionMean(obs), trained->model()->actionMean(obs)));
  EXPECT_TRUE(torch::equal(loaded.model()->value(obs), trained->model()->value(obs)));
  EXPECT_TRUE(torch::equal(loaded.model()->actionStd(), trained->model()->actionStd()));
  EXPECT_TRUE(torch::equal(loaded.normalizer()->mean(), trained->normalizer()->mean()));
  EXPECT_TRUE(torch::equal(loaded.normalizer()->var(), trained->normalizer()->var()));
  EXPECT_EQ(loaded.normalizer()->count(), trained->normalizer()->count());
  EXPECT_EQ(loaded.normalizer()->count(), 3.0 * kSteps * kEnvs);
  EXPECT_TRUE(
      torch::equal(loaded.normalizer()->normalize(obs), trained->normalizer()->normalize(obs)));
  EXPECT_DOUBLE_EQ(loaded.learningRate(), trained->learningRate());
}

TEST_F(CheckpointTest, OptimiserStateRestored) {
  // The same update on the original and on the reloaded learner gives identical parameters only
  // if Adam's moments and step counts were restored; a fresh Adam gives different ones.
  Ppo loaded(testSpec(), testConfig());
  loadCheckpoint(path, loaded);
  Ppo fresh_optimiser(testSpec(), testConfig());
  loadPolicy(path, fresh_optimiser.model(), fresh_optimiser.normalizer());
  fresh_optimiser.setLearningRate(trained->learningRate());

  auto updateWithSeed = [](Ppo& ppo) {
    torch::manual_seed(5);  // the same rollout: same data, same sampled actions
    randomRollout(ppo);
    torch::manual_seed(11);  // same minibatch permutations
    ppo.update();
    return parameters(ppo);
  };
  const auto expected = updateWithSeed(*trained);
  EXPECT_TRUE(sameTensors(updateWithSeed(loaded), expected));
  EXPECT_FALSE(sameTensors(updateWithSeed(fresh_optimiser), expected));
}

TEST_F(CheckpointTest, PolicyActsWithTheScaledClippedMean) {
  Policy policy(path);
  EXPECT_EQ(policy.obsDim(), kObs);
  EXPECT_EQ(policy.actionDim(), kAct);
  policy.setActionLimits({-20.0f, -10.0f}, {20.0f, 30.0f});
  const std::vector<float> obs{0.1f, -2.0f, 5.0f, 1.0f, 0.0f, -1.0f};
  std::vector<float> out;
  policy.act(obs, 2, out);
  ASSERT_EQ(out.size(), 4u);
  const torch::Tensor mean = trained->model()->actionMean(
      trained->normalizer()->normalize(torch::tensor(obs).reshape({2, kObs})));
  for (int e = 0; e < 2; ++e) {
    EXPECT_NEAR(out[e * 2], 20.0 * std::clamp(mean[e][0].item<double>(), -1.0, 1.0), 1e-4);
    EXPECT_NEAR(out[e * 2 + 1], 10.0 + 20.0 * std::clamp(mean[e][1].item<double>(), -1.0, 1.0),
                1e-4);
  }
  EXPECT_THROW(policy.setActionLimits({-1.0f}, {1.0f}), ConfigError);
  EXPECT_THROW(policy.act({1.0f}, 2, out), InputError);
}

TEST_F(CheckpointTest, OtherEnvBoundsThanTheCheckpointsAreNamed) {
  meta.spec = testSpec();  // trained on [-1, 1] per action
  const std::string with_spec = tempPath("with_spec.pt");
  saveCheckpoint(with_spec, *trained, meta);
  Policy policy(with_spec);
  EXPECT_EQ(policy.setActionLimits({-1.0f, -1.0f}, {1.0f, 1.0f}), "");
  const std::string changed = policy.setActionLimits({-20.0f, -1.0f}, {20.0f, 1.0f});
  EXPECT_NE(changed.find("the env's action bounds [-20, 20], [-1, 1] differ from the "
                         "checkpoint's [-1, 1], [-1, 1]"),
            std::string::npos)
      << changed;
  // A checkpoint without a spec (format 1's case) has nothing to compare with.
  EXPECT_EQ(Policy(path).setActionLimits({-20.0f, -1.0f}, {20.0f, 1.0f}), "");
}

TEST_F(CheckpointTest, AnEnvThePolicyIsNotBoundToIsRefusedAndOtherDifferencesAreWarnings) {
  meta.spec = testSpec();
  meta.spec.task = "velocity";
  meta.spec.observation_names = {"a", "b", "c"};
  const std::string with_spec = tempPath("fit_to.pt");
  saveCheckpoint(with_spec, *trained, meta);
  Policy policy(with_spec);
  BatchSpec env = meta.spec;
  env.num_envs = 64;  // a property of the run
  EXPECT_TRUE(policy.fitTo(env).empty());
  env.control_dt = 0.05;
  env.action_high = {2.0f, 1.0f};
  const std::vector<std::string> warnings = policy.fitTo(env);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("the env's action bounds [-1, 2], [-1, 1] differ"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("control_dt: 0.05 differs from 0.0166"), std::string::npos)
      << warnings[1];
  env.observation_names = {"a", "b", "d"};
  try {
    policy.fitTo(env);
    FAIL() << "acted on an env that observes something else";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("observation_names: [a, b, d] differs from [a, b, c]"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(CheckpointTest, TheExportedTorchScriptPolicyActsAsTheCheckpoint) {
  Policy policy(path);
  policy.setActionLimits({-20.0f, -10.0f}, {20.0f, 30.0f});
  BatchSpec spec = testSpec();
  spec.observation_names = {"a", "b", "c"};
  const std::string exported = tempPath("exported/policy.pt");
  policy.exportTorchScript(exported, spec);

  torch::manual_seed(4);
  const torch::Tensor obs = 4.0 * torch::randn({16, kObs});
  const std::vector<float> flat(obs.data_ptr<float>(), obs.data_ptr<float>() + obs.numel());
  std::vector<float> expected;
  policy.act(flat, 16, expected);
  torch::jit::Module module = torch::jit::load(exported);
  const torch::Tensor out = module.forward({obs}).toTensor().contiguous();
  ASSERT_EQ(out.numel(), 32);
  for (int i = 0; i < 32; ++i) EXPECT_NEAR(out.data_ptr<float>()[i], expected[i], 1e-6) << i;
  // Some actions are clipped at the limits and some are not: both paths are compared.
  const auto [lo, hi] = std::minmax_element(expected.begin(), expected.end());
  EXPECT_LT(*lo, 0.0f);
  EXPECT_GT(*hi, 0.0f);

  // PyTorch loads it without this package and computes the same actions; the metadata travels.
  const std::string script = tempPath("check_export.py");
  std::ofstream(script) << "import torch\n"
                           "extra = {'meta.yaml': ''}\n"
                           "m = torch.jit.load('"
                        << exported
                        << "', _extra_files=extra)\n"
                           "obs = torch.tensor([[0.5, -1.0, 2.0]])\n"
                           "print(' '.join('%.6f' % v for v in m(obs)[0].tolist()))\n"
                           "print([l for l in extra['meta.yaml'].decode().splitlines()\n"
                           "       if l.startswith('task:')][0])\n";
  const std::string out_file = tempPath("check_export.out");
  ASSERT_EQ(std::system(("/usr/bin/python3 " + script + " > " + out_file).c_str()), 0);
  std::ifstream result(out_file);
  double left = 0, right = 0;
  std::string meta_line;
  result >> left >> right;
  std::getline(result >> std::ws, meta_line);
  std::vector<float> one;
  policy.act({0.5f, -1.0f, 2.0f}, 1, one);
  EXPECT_NEAR(left, one[0], 1e-5);
  EXPECT_NEAR(right, one[1], 1e-5);
  EXPECT_EQ(meta_line, "task: ");
}

TEST_F(CheckpointTest, ErrorsNameTheFile) {
  try {
    readCheckpointMeta(tempPath("missing.pt"));
    FAIL() << "no error for a missing file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.pt"), std::string::npos) << e.what();
  }
  Ppo other(testSpec(kObs + 1), testConfig());
  EXPECT_THROW(loadCheckpoint(path, other), Error);
  const std::string garbage = tempPath("garbage.pt");
  std::ofstream(garbage) << "not a checkpoint";
  EXPECT_THROW(readCheckpointMeta(garbage), Error);
}

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
