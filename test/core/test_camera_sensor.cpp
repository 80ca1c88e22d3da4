// The camera of every env of a batch: resolved from the robot description's block and the
// camera/... parameters (each value and where it came from), refused with the field named, its
// images in the step result at its cadence, bit for bit on 1 and 2 threads, and no trajectory
// changed by it.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// urdf/jetbot_camera.urdf: the Jetbot with its IMX219 camera block, loaded once.
RobotModelConstPtr cameraJetbot() {
  static const RobotModelConstPtr model =
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf");
  return model;
}

/// A batch of camera Jetbots in a 3 x 3 m arena with two boxes each, 32 x 24 images.
EnvConfig cameraArenaConfig(int num_envs, int threads) {
  EnvConfig c = test::smallConfig(num_envs, threads);
  c.world.arena_size = {3.0, 3.0};
  c.world.num_boxes = 2;
  c.world.random_start = true;
  c.camera.width = 32;
  c.camera.height = 24;
  c.camera.images = {"rgb", "depth", "label"};
  return c;
}

void expectCameraRefused(const EnvConfig& c, const std::string& field) {
  try {
    BatchedEnv env(cameraJetbot(), c);
    ADD_FAILURE() << "accepted; expected an error naming " << field;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(CameraSpec, TheBlocksValuesReachTheCamera) {
  const std::optional<CameraSpec> spec = resolveCamera(CameraConfig(), *cameraJetbot(), 1.0 / 60);
  ASSERT_TRUE(spec);
  EXPECT_EQ(spec->link, "camera_link");
  EXPECT_EQ(spec->intrinsics.width, 224);
  EXPECT_EQ(spec->intrinsics.height, 224);
  EXPECT_DOUBLE_EQ(spec->intrinsics.horizontal_fov, 2.65);
  EXPECT_DOUBLE_EQ(spec->noise_std, 0.007);
  EXPECT_EQ(spec->update_every, 2);  // 30 Hz at a 60 Hz control step
  EXPECT_TRUE(spec->rgb);
  EXPECT_FALSE(spec->depth);  // a camera block, not a depth one
  EXPECT_EQ(spec->image_topic, "camera/image_raw");
  EXPECT_EQ(spec->info_topic, "camera/camera_info");
  EXPECT_EQ(spec->frame, "camera_optical_frame");
  for (const std::string* from : {&spec->size_from, &spec->fov_from, &spec->noise_from,
                                  &spec->update_from, &spec->link_from}) {
    EXPECT_EQ(*from, "Gazebo");
  }
  // The optical frame looks along the camera body's x axis.
  const Eigen::Vector3d axis = spec->optical_in_link.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(axis.x(), 0.95);
}

TEST(CameraSpec, ParametersWinAndSayWhereValuesCameFrom) {
  CameraConfig c;
  c.width = 80;
  c.height = 60;
  c.horizontal_fov = 1.2;
  c.clip = {0.1, 5.0};
  c.distortion = {-0.1, 0.01, 0.0, 0.001, -0.001};
  c.images = {"depth", "label"};
  c.noise_std = 0.0;
  c.update_every = 3;
  const std::optional<CameraSpec> spec = resolveCamera(c, *cameraJetbot(), 1.0 / 60);
  ASSERT_TRUE(spec);
  const CameraIntrinsics& i = spec->intrinsics;
  EXPECT_EQ(i.width, 80);
  EXPECT_EQ(i.height, 60);
  EXPECT_DOUBLE_EQ(i.horizontal_fov, 1.2);
  EXPECT_DOUBLE_EQ(i.near, 0.1);
  EXPECT_DOUBLE_EQ(i.far, 5.0);
  EXPECT_DOUBLE_EQ(i.k1, -0.1);
  EXPECT_DOUBLE_EQ(i.k2, 0.01);
  EXPECT_DOUBLE_EQ(i.p1, 0.001);
  EXPECT_DOUBLE_EQ(i.p2, -0.001);
  EXPECT_FALSE(spec->rgb);
  EXPECT_TRUE(spec->depth);
  EXPECT_TRUE(spec->label);
  EXPECT_DOUBLE_EQ(spec->noise_std, 0.0);
  EXPECT_EQ(spec->update_every, 3);
  EXPECT_EQ(spec->size_from, "camera/width, camera/height");
  EXPECT_EQ(spec->clip_from, "camera/clip");
  EXPECT_EQ(spec->distortion_from, "camera/distortion");
  EXPECT_EQ(spec->images_from, "camera/images");
  EXPECT_EQ(spec->update_from, "camera/update_every");
  // Disabled: no camera, whatever the block says.
  c.enabled = false;
  EXPECT_FALSE(resolveCamera(c, *cameraJetbot(), 1.0 / 60));
}

TEST(CameraSpec, ALinkWithoutABlockGetsACameraOfTheParameters) {
  EXPECT_FALSE(resolveCamera(CameraConfig(), *test::jetbot(), 1.0 / 60));  // no block, no link
  CameraConfig c;
  c.link = "base_link";
  const std::optional<CameraSpec> spec = resolveCamera(c, *test::jetbot(), 1.0 / 60);
  ASSERT_TRUE(spec);
  EXPECT_EQ(spec->intrinsics.width, 64);
  EXPECT_EQ(spec->intrinsics.height, 64);
  EXPECT_EQ(spec->update_every, 1);
  EXPECT_EQ(spec->size_from, "default");
  EXPECT_EQ(spec->frame, "base_link_optical_frame");
}

TEST(CameraSpec, BadValuesAreRefusedNamingTheField) {
  EnvConfig c = test::smallConfig(1);
  c.camera.link = "no_such_link";
  expectCameraRefused(c, "camera/link");
  c = test::smallConfig(1);
  c.camera.width = 5000;
  expectCameraRefused(c, "camera/width");
  c = test::smallConfig(1);
  c.camera.horizontal_fov = 3.2;
  expectCameraRefused(c, "camera/horizontal_fov");
  c = test::smallConfig(1);
  c.camera.clip = {1.0, 0.5};
  expectCameraRefused(c, "camera/clip/far");
  c = test::smallConfig(1);
  c.camera.clip = {0.1};
  expectCameraRefused(c, "camera/clip");
  c = test::smallConfig(1);
  c.camera.distortion = {0.1, 0.2};
  expectCameraRefused(c, "camera/distortion");
  c = test::smallConfig(1);
  c.camera.images = {"rgb", "infrared"};
  expectCameraRefused(c, "camera/images");
  c = test::smallConfig(1);
  c.camera.noise_std = -0.5;
  expectCameraRefused(c, "camera/noise_std");
}

TEST(CameraBatch, ImagesInTheStepResultAtTheCamerasCadence) {
  EnvConfig c = cameraArenaConfig(3, 1);
  c.camera.update_every = 2;
  BatchedEnv env(cameraJetbot(), c);
  ASSERT_NE(env.camera(), nullptr);
  const BatchImages& images = env.state().images;
  EXPECT_EQ(images.width, 32);
  EXPECT_EQ(images.height, 24);
  EXPECT_EQ(images.rgb.size(), 3u * 32 * 24 * 3);
  EXPECT_EQ(images.depth.size(), 3u * 32 * 24);
  EXPECT_EQ(images.label.size(), 3u * 32 * 24);
  EXPECT_EQ(images.fresh, std::vector<std::uint8_t>(3, 1));  // made at the reset
  const std::vector<float> still(3 * 2, 0.0f);
  env.step(still);
  EXPECT_EQ(env.state().images.fresh, std::vector<std::uint8_t>(3, 0));
  env.step(still);
  EXPECT_EQ(env.state().images.fresh, std::vector<std::uint8_t>(3, 1));
  // The view reads the same pixels; the arena's walls and the ground are in every image.
  const EnvImages view = env.view(1).images();
  EXPECT_EQ(view.depth, &images.depth[32 * 24]);
  int ground = 0, wall = 0;
  for (int i = 0; i < 32 * 24; ++i) {
    ground += view.label[i] == static_cast<std::uint8_t>(SurfaceClass::kGround);
    wall += view.label[i] == static_cast<std::uint8_t>(SurfaceClass::kWall);
  }
  EXPECT_GT(ground, 0);
  EXPECT_GT(wall + ground, 32 * 24 / 2);
  EXPECT_TRUE(env.view(1).imaged());
}

TEST(CameraBatch, ImagesAreBitForBitOnOneAndTwoThreads) {
  EnvConfig one_config = cameraArenaConfig(4, 1);
  one_config.camera.noise_std = 0.02;  // the noise streams too
  EnvConfig two_config = one_config;
  two_config.num_threads = 2;
  BatchedEnv one(cameraJetbot(), one_config), two(cameraJetbot(), two_config);
  for (int step = 0; step < 12; ++step) {
    const std::vector<float> actions = test::randomActions(4, step);
    const BatchImages& a = one.step(actions).images;
    const BatchImages& b = two.step(actions).images;
    ASSERT_EQ(a.rgb, b.rgb) << "step " << step;
    ASSERT_EQ(0, std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)));
    ASSERT_EQ(a.label, b.label);
  }
  // A reset with a seed restarts the noise: the same images again.
  const std::vector<std::uint8_t> before = one.reset({}, 7).images.rgb;
  EXPECT_EQ(one.reset({}, 7).images.rgb, before);
}

TEST(CameraBatch, TheCameraChangesNoTrajectory) {
  EnvConfig seen = cameraArenaConfig(3, 1);
  seen.camera.noise_std = 0.05;
  EnvConfig blind = seen;
  blind.camera.enabled = false;
  BatchedEnv a(cameraJetbot(), seen), b(cameraJetbot(), blind);
  EXPECT_EQ(b.camera(), nullptr);
  EXPECT_TRUE(b.state().images.rgb.empty());
  for (int step = 0; step < 40; ++step) {
    const std::vector<float> actions = test::randomActions(3, step);
    ASSERT_TRUE(test::bitEqual(a.step(actions).observations, b.step(actions).observations))
        << "step " << step;
    ASSERT_EQ(a.state().reset_env_ids, b.state().reset_env_ids);
  }
}

}  // namespace
}  // namespace jetbot_rl
