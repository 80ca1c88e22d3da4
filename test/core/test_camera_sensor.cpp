// The camera of every env of a batch: resolved from the robot description's block and the
// camera/... parameters (each value and where it came from), refused with the field named, its
// images in the step result at its cadence, bit for bit on 1 and 2 threads, and no trajectory
// changed by it.
#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <string>

#include "camera_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// The one camera `config` gives on `robot`, or none.
std::optional<CameraSpec> oneCamera(const CameraConfig& config, const RobotModel& robot) {
  const std::vector<CameraSpec> cameras = resolveCameras(config, robot, 1.0 / 60);
  EXPECT_LE(cameras.size(), 1u);
  if (cameras.empty()) return std::nullopt;
  return cameras.front();
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
  const std::optional<CameraSpec> spec = oneCamera(CameraConfig(), *cameraJetbot());
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
  const std::optional<CameraSpec> spec = oneCamera(c, *cameraJetbot());
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
  EXPECT_FALSE(oneCamera(c, *cameraJetbot()));
}

TEST(CameraSpec, ALinkWithoutABlockGetsACameraOfTheParameters) {
  EXPECT_FALSE(oneCamera(CameraConfig(), *test::jetbot()));  // no block, no link
  CameraConfig c;
  c.link = "base_link";
  const std::optional<CameraSpec> spec = oneCamera(c, *test::jetbot());
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
  c = test::smallConfig(1);
  c.camera.light_intensity = {2.0, 1.0};
  expectCameraRefused(c, "camera/light_intensity");
  c = test::smallConfig(1);
  c.camera.exposure = {1.0};
  expectCameraRefused(c, "camera/exposure");
  c = test::smallConfig(1);
  c.camera.pose_jitter = {0.1};
  expectCameraRefused(c, "camera/pose_jitter");
}

TEST(CameraBatch, EveryRandomStreamHasAPurposeOfItsOwn) {
  // Stream e + offset per purpose: offsets 2^40 apart keep the streams of every env id below 2^40
  // apart (the camera's noise once shared the people's offset).
  const std::vector<std::uint64_t> offsets{streams::kNoise, streams::kScan, streams::kMovers,
                                           streams::kCamera, streams::kAppearance};
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    EXPECT_GE(offsets[i], 1ULL << 40) << i;
    for (std::size_t j = i + 1; j < offsets.size(); ++j) {
      const std::uint64_t gap =
          offsets[i] > offsets[j] ? offsets[i] - offsets[j] : offsets[j] - offsets[i];
      EXPECT_GE(gap, 1ULL << 40) << i << " and " << j;
    }
  }
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

TEST(CameraBatch, AnEndedEpisodesLastImagesAreItsFinalImages) {
  // Two batches alike but for their episodes' length: where the short one's episodes end, the
  // long one's images at that step are what the short one keeps as the final images.
  EnvConfig short_config = cameraArenaConfig(3, 1);
  short_config.camera.noise_std = 0.02;
  short_config.episode_length_s = 0.5;
  EnvConfig long_config = short_config;
  long_config.episode_length_s = 5.0;
  BatchedEnv a(cameraJetbot(), short_config), b(cameraJetbot(), long_config);
  const std::size_t pixels = 32 * 24;
  bool ended = false;
  for (int step = 0; step < a.maxEpisodeLength() && !ended; ++step) {
    const std::vector<float> actions = test::randomActions(3, step);
    const StepResult& ra = a.step(actions);
    const StepResult& rb = b.step(actions);
    if (ra.reset_env_ids.empty()) {
      ASSERT_TRUE(ra.final_images.rgb.empty());
      ASSERT_EQ(ra.images.rgb, rb.images.rgb) << "step " << step;
      continue;
    }
    ended = true;
    ASSERT_EQ(ra.reset_env_ids, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(ra.final_images.width, 32);
    EXPECT_EQ(ra.final_images.rgb, rb.images.rgb);
    EXPECT_EQ(ra.final_images.label, rb.images.label);
    ASSERT_EQ(ra.final_images.depth.size(), 3 * pixels);
    EXPECT_EQ(0, std::memcmp(ra.final_images.depth.data(), rb.images.depth.data(),
                             3 * pixels * sizeof(float)));
    EXPECT_NE(ra.images.rgb, rb.images.rgb);  // the new episodes' first images
  }
  EXPECT_TRUE(ended);
  EXPECT_TRUE(a.reset().final_images.rgb.empty());
  // Without batch_images nothing is kept, and the spec names no images.
  EXPECT_EQ(a.spec().image_kinds, (std::vector<std::string>{"rgb", "depth", "label"}));
  EXPECT_EQ(a.spec().image_width, 32);
  short_config.camera.batch_images = false;
  BatchedEnv c(cameraJetbot(), short_config);
  EXPECT_TRUE(c.spec().image_kinds.empty());
  EXPECT_EQ(c.spec().image_height, 0);
  for (int step = 0; step < c.maxEpisodeLength(); ++step) {
    EXPECT_TRUE(c.step(test::randomActions(3, step)).final_images.rgb.empty());
  }
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

/// A floor YAML `name`.yaml beside a binary PPM of `width` x `height` pixels (`rgb`, top row
/// first) at `resolution` with `origin`; its path.
std::string floorFiles(const std::string& name, int width, int height,
                       const std::vector<std::uint8_t>& rgb, double resolution,
                       const std::string& origin) {
  std::string ppm = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
  ppm.append(rgb.begin(), rgb.end());
  test::writeTempFile(name + ".ppm", ppm);
  return test::writeTempFile(name + ".yaml", "image: " + name +
                                                 ".ppm\nresolution: " + std::to_string(resolution) +
                                                 "\norigin: " + origin + "\n");
}

void expectFloorRefused(const std::string& yaml, const std::string& text) {
  try {
    FloorImage::fromYamlFile(yaml);
    ADD_FAILURE() << "accepted; expected an error naming " << text;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("world/floor"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(CameraFloor, TheFloorImageLiesOnTheGroundAsAMapIsPlaced) {
  // Two pixels of 1 m: red over x in [-1, 0), blue over [0, 1), y in [-0.5, 0.5).
  const std::string yaml =
      floorFiles("floor_two", 2, 1, {255, 0, 0, 0, 0, 255}, 1.0, "[-1.0, -0.5, 0.0]");
  auto floor = std::make_shared<const FloorImage>(FloorImage::fromYamlFile(yaml));
  Eigen::Vector3f c;
  ASSERT_TRUE(floor->colourAt(-0.5f, 0.0f, c));
  EXPECT_EQ(c, Eigen::Vector3f(1.0f, 0.0f, 0.0f));
  ASSERT_TRUE(floor->colourAt(0.5f, 0.2f, c));
  EXPECT_EQ(c, Eigen::Vector3f(0.0f, 0.0f, 1.0f));
  EXPECT_FALSE(floor->colourAt(1.5f, 0.0f, c));
  EXPECT_FALSE(floor->colourAt(0.0f, 0.6f, c));
  // A camera 1 m up looking straight down: the ground left of x = 0 red, right of it blue; the
  // label is the ground's either way.
  const CameraWorld world(nullptr, floor);
  CameraEnvScene scene(world);
  CameraIntrinsics intrinsics;
  intrinsics.width = 16;
  intrinsics.height = 16;
  intrinsics.horizontal_fov = 0.8;
  const CameraModel model(intrinsics);
  const Eigen::Isometry3d down = opticalFrame(Eigen::Translation3d(0.0, 0.0, 1.0) *
                                              Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()));
  CameraImages images;
  scene.render(model, down, images);
  int red = 0, blue = 0;
  for (int i = 0; i < 16 * 16; ++i) {
    const std::uint8_t* p = &images.rgb[3 * i];
    red += p[0] > 200 && p[1] == 0 && p[2] == 0;
    blue += p[2] > 200 && p[0] == 0 && p[1] == 0;
    EXPECT_EQ(images.label[i], static_cast<std::uint8_t>(SurfaceClass::kGround));
  }
  EXPECT_EQ(red, 16 * 8);
  EXPECT_EQ(blue, 16 * 8);
}

TEST(CameraFloor, BadFloorFilesAreRefusedNamingTheFieldAndFile) {
  expectFloorRefused(::testing::TempDir() + "no_floor.yaml", "no_floor.yaml");
  expectFloorRefused(test::writeTempFile("floor_no_res.yaml", "image: x.ppm\norigin: [0, 0, 0]\n"),
                     "resolution");
  expectFloorRefused(
      test::writeTempFile("floor_no_image.yaml",
                          "image: missing.ppm\nresolution: 0.1\norigin: [0, 0, 0]\n"),
      "missing.ppm");
  expectFloorRefused(floorFiles("floor_bad_res", 1, 1, {1, 2, 3}, -0.5, "[0, 0, 0]"), "resolution");
  // A huge image is refused from its header, before it is decoded.
  expectFloorRefused(
      floorFiles("floor_huge", 9000, 1, std::vector<std::uint8_t>(27000, 7), 0.1, "[0, 0, 0]"),
      "at most 8192 px");
  EnvConfig c = cameraArenaConfig(1, 1);
  c.world.floor = ::testing::TempDir() + "no_floor.yaml";
  expectCameraRefused(c, "world/floor");
}

TEST(CameraBatch, AppearanceRandomisationChangesImagesNotTrajectories) {
  EnvConfig plain = cameraArenaConfig(3, 1);
  EnvConfig looks = plain;  // colours, light and exposure: the geometry stays
  looks.camera.random_colours = true;
  looks.camera.light_intensity = {0.5, 1.5};
  looks.camera.random_light_direction = true;
  looks.camera.exposure = {0.8, 1.2};
  EnvConfig jittered = looks;
  jittered.camera.pose_jitter = {0.02, 0.05};
  BatchedEnv a(cameraJetbot(), plain), b(cameraJetbot(), looks), b2(cameraJetbot(), looks),
      c(cameraJetbot(), jittered);
  for (int step = 0; step < 30; ++step) {
    const std::vector<float> actions = test::randomActions(3, step);
    const StepResult& ra = a.step(actions);
    const StepResult& rb = b.step(actions);
    const StepResult& rc = c.step(actions);
    ASSERT_TRUE(test::bitEqual(ra.observations, rb.observations)) << "step " << step;
    ASSERT_TRUE(test::bitEqual(ra.observations, rc.observations)) << "step " << step;
    EXPECT_NE(ra.images.rgb, rb.images.rgb);
    EXPECT_EQ(ra.images.label, rb.images.label);  // the same surfaces, seen from the same pose
    ASSERT_EQ(0, std::memcmp(ra.images.depth.data(), rb.images.depth.data(),
                             ra.images.depth.size() * sizeof(float)));
    EXPECT_NE(0, std::memcmp(ra.images.depth.data(), rc.images.depth.data(),
                             ra.images.depth.size() * sizeof(float)));
    EXPECT_EQ(b2.step(actions).images.rgb, rb.images.rgb);  // the same seed, the same looks
  }
  // Each env and each episode draws its own: the sky of env 0 and env 1 (top-left pixel, above
  // the walls) differs in brightness with their exposures, and changes with a new episode.
  const auto sky = [](const BatchedEnv& env, int e) {
    const EnvImages im = env.view(e).images();
    return std::vector<std::uint8_t>(im.rgb, im.rgb + 3);
  };
  EXPECT_NE(sky(b, 0), sky(b, 1));
  const std::vector<std::uint8_t> before = sky(b, 0);
  b.reset({0});
  EXPECT_NE(sky(b, 0), before);
}

}  // namespace
}  // namespace jetbot_rl
