// An image policy (the road following task's): its encoder refuses images its layers cannot take,
// naming the field and the layer; PPO learns on a camera batch with the pixels kept as bytes; the
// checkpoint's Policy acts on images as the learner's model does, and the exported TorchScript
// (forward(obs, image uint8)) as the Policy; with memory (a GRU or an LSTM after the encoder) the
// update's sequences recompute what acting computed and the export carries the memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/image_frames.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ppo.h"
#include "jetbot_rl/ppo/ppo_checkpoint.h"
#include "jetbot_rl/ppo/torch_api.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string imageTempPath(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_image_policy";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

/// Road following on 6 camera Jetbots, 24 x 24 images every step.
std::unique_ptr<BatchedEnv> cameraBatch() {
  EnvConfig c;
  c.num_envs = 6;
  c.num_threads = 1;
  c.camera.width = 24;
  c.camera.height = 24;
  c.camera.update_every = 1;
  TaskConfig t;
  t.task = TaskKind::kRoadFollowing;
  t.road.random_colours = true;
  return std::make_unique<BatchedEnv>(
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf"), c,
      makeTask(t));
}

/// Saves `ppo` (trained on `spec` with `config`) as a checkpoint at imageTempPath(`name`); its
/// path.
std::string saveImageCheckpoint(Ppo& ppo, const BatchSpec& spec, const PpoConfig& config,
                                const std::string& name) {
  CheckpointMeta meta;
  meta.obs_dim = spec.obs_dim;
  meta.action_dim = spec.action_dim;
  meta.config = config;
  meta.spec = spec;
  meta.spec.num_envs = 0;
  const std::string path = imageTempPath(name);
  saveCheckpoint(path, ppo, meta);
  return path;
}

PpoConfig imageConfig() {
  PpoConfig c;
  c.actor_hidden_dims = {16};
  c.critic_hidden_dims = {16};
  c.conv_channels = {4, 8};
  c.conv_kernels = {5, 3};
  c.conv_strides = {2, 2};
  c.image_features = 16;
  c.image_grayscale = true;
  c.num_steps_per_env = 8;
  c.num_mini_batches = 2;
  c.num_learning_epochs = 2;
  return c;
}

void expectEncoderRefused(const NetworkConfig& c, ImageShape shape, const std::string& words) {
  try {
    ImageEncoder encoder(c, shape);
    (void)encoder;
    ADD_FAILURE() << "accepted; expected " << words;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("conv_kernels"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ImageEncoder, RefusesAnImageItsLayersCannotTakeNamingTheLayer) {
  NetworkConfig c;
  c.conv_channels = {8, 16, 16};
  c.conv_kernels = {5, 5, 5};
  c.conv_strides = {2, 2, 2};
  expectEncoderRefused(c, {16, 16}, "convolution 2 gets a 1 x 1 px image");  // 16 -> 6 -> 1
  EXPECT_NO_THROW(ImageEncoder(c, ImageShape{32, 32}));                      // 32 -> 14 -> 5 -> 1
  c.conv_strides = {2, 2};
  expectEncoderRefused(c, {32, 32}, "as many values");
}

TEST(ImagePolicy, LearnsFromBytesAndActsAsItsCheckpointAndItsExport) {
  torch::manual_seed(3);
  std::unique_ptr<BatchedEnv> env = cameraBatch();
  const BatchSpec spec = env->spec();
  ASSERT_EQ(spec.observer.camera_image, "rgb");
  const PpoConfig config = imageConfig();
  Ppo ppo(spec, config);
  ASSERT_EQ(ppo.model()->imageValues(), 24 * 24 * 3);
  const torch::Tensor before = ppo.model()->imageEncoder()->linear()->weight.clone();
  const std::vector<std::uint8_t> first_images = env->state().images.rgb;
  for (int t = 0; t < config.num_steps_per_env; ++t) {
    const std::vector<float> actions = ppo.act(env->state());
    ppo.processEnvStep(env->step(actions));
  }
  // The rollout keeps the pixels as the bytes the env made.
  const torch::Tensor stored = ppo.storage().images();
  ASSERT_EQ(stored.scalar_type(), torch::kUInt8);
  const torch::Tensor step0 = stored[0].contiguous();
  EXPECT_TRUE(std::equal(first_images.begin(), first_images.end(), step0.data_ptr<std::uint8_t>()));
  ppo.computeReturns(env->state());
  const UpdateStats stats = ppo.update();
  EXPECT_TRUE(std::isfinite(stats.value_loss));
  EXPECT_FALSE(torch::equal(before, ppo.model()->imageEncoder()->linear()->weight));  // it learnt

  const std::string path = saveImageCheckpoint(ppo, spec, config, "image_policy.pt");
  Policy policy(path);
  ASSERT_TRUE(policy.observesImage());
  const StepResult& state = env->state();
  std::vector<float> actions;
  policy.act(state.observations, state.images.rgb, spec.num_envs, actions);
  // The learner's model, acting with its mean on the same input.
  torch::Tensor input = torch::cat(
      {ppo.normalizer()->normalize(torch::from_blob(const_cast<float*>(state.observations.data()),
                                                    {spec.num_envs, spec.obs_dim}, torch::kFloat)),
       torch::from_blob(const_cast<std::uint8_t*>(state.images.rgb.data()),
                        {spec.num_envs, 24 * 24 * 3}, torch::kUInt8)
           .to(torch::kFloat)},
      -1);
  const torch::Tensor mean = torch::clamp(ppo.model()->actionMean(input), -1.0, 1.0) * 20.0;
  for (int i = 0; i < spec.num_envs * 2; ++i) {
    EXPECT_NEAR(actions[i], mean.flatten()[i].item<float>(), 1e-4) << i;
  }
  std::vector<float> no_image;
  EXPECT_THROW(policy.act(state.observations, spec.num_envs, no_image), InputError);
  EXPECT_THROW(policy.act(state.observations, {1, 2, 3}, spec.num_envs, no_image), InputError);

  const std::string exported = imageTempPath("image_policy_export.pt");
  policy.exportTorchScript(exported, spec);
  torch::jit::Module module = torch::jit::load(exported);
  const torch::Tensor obs = torch::from_blob(const_cast<float*>(state.observations.data()),
                                             {spec.num_envs, spec.obs_dim}, torch::kFloat);
  const torch::Tensor image = torch::from_blob(const_cast<std::uint8_t*>(state.images.rgb.data()),
                                               {spec.num_envs, 24, 24, 3}, torch::kUInt8);
  const torch::Tensor out = module.forward({obs, image}).toTensor().contiguous();
  ASSERT_EQ(out.numel(), spec.num_envs * 2);
  for (int i = 0; i < spec.num_envs * 2; ++i) {
    EXPECT_NEAR(out.data_ptr<float>()[i], actions[i], 1e-5) << i;
  }
}

/// Image policies with memory: the GRU or LSTM takes the vector's history and the image's features.
class ImageMemoryTest : public testing::TestWithParam<RnnType> {};

TEST_P(ImageMemoryTest, SequencesRecomputeActingAndTheExportCarriesTheMemory) {
  torch::manual_seed(4);
  std::unique_ptr<BatchedEnv> env = cameraBatch();
  const BatchSpec spec = env->spec();
  PpoConfig config = imageConfig();
  config.rnn_type = GetParam();
  config.rnn_hidden_size = 8;
  config.obs_history_length = 2;
  config.action_history_length = 1;
  Ppo ppo(spec, config);
  ASSERT_TRUE(ppo.model()->recurrent());
  for (int t = 0; t < config.num_steps_per_env; ++t) {
    const std::vector<float> actions = ppo.act(env->state());
    ppo.processEnvStep(env->step(actions));
  }
  ppo.computeReturns(env->state());
  int batches = 0;
  for (const MiniBatch& b : ppo.storage().sequenceMiniBatches(config.num_mini_batches)) {
    torch::NoGradGuard no_grad;
    const ActionEvaluation e = ppo.model()->evaluateSequence(b.obs, b.actions, b.state, b.starts);
    EXPECT_TRUE(torch::allclose(e.mean, b.old_mean, 0.0, 1e-5));
    EXPECT_TRUE(torch::allclose(e.values, b.old_values, 0.0, 1e-5));
    ++batches;
  }
  EXPECT_EQ(batches, config.num_mini_batches);
  const torch::Tensor encoder_before = ppo.model()->imageEncoder()->linear()->weight.clone();
  const torch::Tensor rnn_before = ppo.model()->actorMemory()->layers()[0].w_ih.clone();
  const UpdateStats stats = ppo.update();
  EXPECT_TRUE(std::isfinite(stats.value_loss));
  EXPECT_FALSE(torch::equal(encoder_before, ppo.model()->imageEncoder()->linear()->weight));
  EXPECT_FALSE(torch::equal(rnn_before, ppo.model()->actorMemory()->layers()[0].w_ih));

  const std::string path =
      saveImageCheckpoint(ppo, spec, config, "image_memory_" + enumName(GetParam()) + ".pt");
  Policy policy(path);
  ASSERT_TRUE(policy.observesImage());
  ASSERT_TRUE(policy.hasMemory());
  const std::string exported = imageTempPath("image_memory_export.pt");
  policy.exportTorchScript(exported, spec);
  torch::jit::Module module = torch::jit::load(exported);
  const int n = spec.num_envs;
  torch::Tensor hidden = module.run_method("initial_hidden", n).toTensor();
  std::vector<std::vector<float>> played;
  for (int t = 0; t < 5; ++t) {
    const StepResult& state = env->state();
    std::vector<float> expected;
    policy.act(state.observations, state.images.rgb, n, expected);
    const auto out =
        module
            .forward({torch::from_blob(const_cast<float*>(state.observations.data()),
                                       {n, spec.obs_dim}, torch::kFloat),
                      torch::from_blob(const_cast<std::uint8_t*>(state.images.rgb.data()),
                                       {n, 24, 24, 3}, torch::kUInt8),
                      hidden})
            .toTuple();
    const torch::Tensor actions = out->elements()[0].toTensor().contiguous();
    hidden = out->elements()[1].toTensor();
    ASSERT_EQ(actions.numel(), n * 2);
    for (int i = 0; i < n * 2; ++i) {
      EXPECT_NEAR(actions.data_ptr<float>()[i], expected[i], 1e-5) << "step " << t << ", " << i;
    }
    played.push_back(expected);
    const StepResult& next = env->step(expected);
    std::vector<std::uint32_t> ended(next.reset_env_ids.begin(), next.reset_env_ids.end());
    policy.resetMemory(ended);  // an ended episode starts over in both
    for (std::uint32_t e : ended) hidden[e].zero_();
  }
  EXPECT_NE(played.front(), played.back());
}

INSTANTIATE_TEST_SUITE_P(GruAndLstm, ImageMemoryTest,
                         testing::Values(RnnType::kGru, RnnType::kLstm),
                         [](const testing::TestParamInfo<RnnType>& info) {
                           return enumName(info.param);
                         });

TEST(ImageFrames, StackNewestFirstAndStartOverWithTheFirstImage) {
  ImageFrames frames(2, 2, 3);
  const auto pixels = [](std::vector<float> v) { return torch::tensor(v).view({2, 2}); };
  const auto fresh = [](int a, int b) { return torch::tensor({a, b}).to(torch::kBool); };
  const auto row = [](const torch::Tensor& t, int r) {
    const torch::Tensor c = t[r].contiguous();
    return std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
  };
  torch::Tensor s = frames.push(pixels({1, 2, 3, 4}), fresh(true, true));
  EXPECT_EQ(row(s, 0), (std::vector<float>{1, 2, 1, 2, 1, 2}));
  s = frames.push(pixels({5, 6, 7, 8}), fresh(false, true));
  EXPECT_EQ(row(s, 0), (std::vector<float>{5, 6, 1, 2, 1, 2}));  // newest first
  EXPECT_EQ(row(s, 1), (std::vector<float>{7, 8, 7, 8, 7, 8}));  // started over
  const torch::Tensor peeked =
      frames.peek(torch::tensor(std::vector<int64_t>{0}), torch::tensor({9.0f, 10.0f}).view({1, 2}),
                  torch::zeros({1}, torch::kBool));
  EXPECT_EQ(row(peeked, 0), (std::vector<float>{9, 10, 5, 6, 1, 2}));
  s = frames.push(pixels({255, 0, 0, 255}), fresh(false, false));  // peek changed nothing
  EXPECT_EQ(row(s, 0), (std::vector<float>{255, 0, 5, 6, 1, 2}));
  EXPECT_EQ(row(s, 1), (std::vector<float>{0, 255, 7, 8, 7, 8}));
}

TEST(ImageFrames, AreRefusedWithoutAnImage) {
  NetworkConfig c;
  c.image_frames = 2;
  try {
    ActorCritic model(4, 2, c);
    ADD_FAILURE() << "image_frames 2 accepted without an image";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("image_frames = 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no camera_image"), std::string::npos) << e.what();
  }
}

/// A frame stack of 3 images, alone (grey) or with a history and a GRU (colour).
class FrameStackTest : public testing::TestWithParam<RnnType> {};

TEST_P(FrameStackTest, LearnsKeepsItsFramesInTheRolloutAndTheExportStacksThemAsActing) {
  torch::manual_seed(5);
  std::unique_ptr<BatchedEnv> env = cameraBatch();
  const BatchSpec spec = env->spec();
  PpoConfig config = imageConfig();
  config.image_frames = 3;
  config.rnn_type = GetParam();
  if (GetParam() != RnnType::kNone) {
    config.rnn_hidden_size = 8;
    config.obs_history_length = 2;
    config.image_grayscale = false;
  }
  Ppo ppo(spec, config);
  const int v = 24 * 24 * 3;
  ASSERT_EQ(ppo.model()->imageValues(), 3 * v);
  const std::vector<std::uint8_t> first = env->state().images.rgb;
  std::vector<std::uint8_t> second;
  for (int t = 0; t < config.num_steps_per_env; ++t) {
    const std::vector<float> actions = ppo.act(env->state());
    ppo.processEnvStep(env->step(actions));
    if (t == 0) second = env->state().images.rgb;
  }
  // Step 0 stacks env 0's first image three times; step 1 its second image, then the first.
  const torch::Tensor stored = ppo.storage().images();
  ASSERT_EQ(stored.size(2), 3 * v);
  const auto bytes = [&](int step, int frame) {
    const torch::Tensor t = stored[step][0].narrow(0, frame * v, v).contiguous();
    return std::vector<std::uint8_t>(t.data_ptr<std::uint8_t>(), t.data_ptr<std::uint8_t>() + v);
  };
  const std::vector<std::uint8_t> first0(first.begin(), first.begin() + v);
  const std::vector<std::uint8_t> second0(second.begin(), second.begin() + v);
  ASSERT_NE(first0, second0);
  for (int f = 0; f < 3; ++f) EXPECT_EQ(bytes(0, f), first0) << f;
  EXPECT_EQ(bytes(1, 0), second0);
  EXPECT_EQ(bytes(1, 1), first0);
  EXPECT_EQ(bytes(1, 2), first0);
  ppo.computeReturns(env->state());
  const torch::Tensor before = ppo.model()->imageEncoder()->linear()->weight.clone();
  EXPECT_TRUE(std::isfinite(ppo.update().value_loss));
  EXPECT_FALSE(torch::equal(before, ppo.model()->imageEncoder()->linear()->weight));

  const std::string path =
      saveImageCheckpoint(ppo, spec, config, "frame_stack_" + enumName(GetParam()) + ".pt");
  Policy policy(path);
  ASSERT_TRUE(policy.hasMemory());
  const std::string exported = imageTempPath("frame_stack_export.pt");
  policy.exportTorchScript(exported, spec);
  torch::jit::Module module = torch::jit::load(exported);
  const int n = spec.num_envs;
  torch::Tensor hidden = module.run_method("initial_hidden", n).toTensor();
  std::vector<std::vector<float>> played;
  int resets = 0;
  for (int t = 0; t < 12; ++t) {
    const StepResult& state = env->state();
    std::vector<float> expected;
    policy.act(state.observations, state.images.rgb, n, expected);
    const auto out =
        module
            .forward({torch::from_blob(const_cast<float*>(state.observations.data()),
                                       {n, spec.obs_dim}, torch::kFloat),
                      torch::from_blob(const_cast<std::uint8_t*>(state.images.rgb.data()),
                                       {n, 24, 24, 3}, torch::kUInt8),
                      hidden})
            .toTuple();
    const torch::Tensor actions = out->elements()[0].toTensor().contiguous();
    hidden = out->elements()[1].toTensor();
    ASSERT_EQ(actions.numel(), n * 2);
    for (int i = 0; i < n * 2; ++i) {
      EXPECT_NEAR(actions.data_ptr<float>()[i], expected[i], 1e-5) << "step " << t << ", " << i;
    }
    played.push_back(expected);
    // Env 1 starts over every fourth step in both, whether or not its episode ended.
    const StepResult& next = env->step(expected);
    std::vector<std::uint32_t> ended(next.reset_env_ids.begin(), next.reset_env_ids.end());
    if (t % 4 == 3 && std::find(ended.begin(), ended.end(), 1u) == ended.end()) ended.push_back(1);
    resets += static_cast<int>(ended.size());
    policy.resetMemory(ended);
    for (std::uint32_t e : ended) hidden[e].zero_();
  }
  EXPECT_GT(resets, 0);
  EXPECT_NE(played.front(), played.back());
}

INSTANTIATE_TEST_SUITE_P(AloneAndWithMemory, FrameStackTest,
                         testing::Values(RnnType::kNone, RnnType::kGru),
                         [](const testing::TestParamInfo<RnnType>& info) {
                           return enumName(info.param);
                         });

}  // namespace
}  // namespace ppo
}  // namespace jetbot_rl
