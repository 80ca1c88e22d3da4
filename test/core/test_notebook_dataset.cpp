// The Jetbot notebooks' data sets: an image is blocked when a wall lies close ahead and free when
// it is far, the road target lands where the centreline ahead is seen, and the writer balances
// the classes and names the road images by their target's pixel.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <filesystem>
#include <string>

#include "camera_test_util.h"
#include "jetbot_rl/dataset/notebook_dataset.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/tasks/task_factory.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

EnvConfig datasetConfig(int num_envs) {
  EnvConfig c = test::smallConfig(num_envs);
  c.camera.width = 48;
  c.camera.height = 48;
  c.camera.update_every = 1;
  c.camera.noise_std = 0.0;
  c.camera.images = {"rgb", "depth", "label"};
  c.world.arena_size = {3.0, 3.0};
  return c;
}

std::string datasetDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "jetbot_rl_test_dataset" / name;
  std::filesystem::remove_all(dir);
  return dir.string();
}

int filesIn(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    int w = 0, h = 0, channels = 0;
    EXPECT_TRUE(stbi_info(f.path().c_str(), &w, &h, &channels)) << f.path();
    EXPECT_EQ(w, 48) << f.path();
    ++n;
  }
  return n;
}

TEST(NotebookDataset, AWallCloseAheadBlocksAndOneFarAwayDoesNot) {
  BatchedEnv env(cameraJetbot(), datasetConfig(1));
  const std::vector<float> stop = test::uniformActions(env, 0.0f, 0.0f);
  const CameraModel model(env.camera()->intrinsics);
  test::place(env, 0, {1.3, 0.0}, 0.0);  // the wall at x = 1.5: 0.2 m ahead
  env.step(stop);
  EXPECT_TRUE(blockedAhead(env, model, 0, 0.3, 0.1));
  EXPECT_FALSE(blockedAhead(env, model, 0, 0.1, 0.1));
  test::place(env, 0, {1.3, 0.0}, 3.14159);  // facing the far wall, 2.8 m away
  env.step(stop);
  EXPECT_FALSE(blockedAhead(env, model, 0, 0.3, 0.1));
}

TEST(NotebookDataset, BalancedBlockedAndFreeImages) {
  EnvConfig c = datasetConfig(4);
  c.world.random_start = true;
  c.randomization.initial_yaw = {-3.14159, 3.14159};
  BatchedEnv env(cameraJetbot(), c);
  DatasetOptions o;
  o.out = datasetDir("collision");
  o.count = 6;
  o.blocked_distance = 0.5;
  const DatasetSummary s = writeNotebookDataset(env, o);
  EXPECT_EQ(s.blocked, 3);
  EXPECT_EQ(s.free, 3);
  EXPECT_EQ(filesIn(std::filesystem::path(o.out) / "blocked"), 3);
  EXPECT_EQ(filesIn(std::filesystem::path(o.out) / "free"), 3);
}

TEST(NotebookDataset, RoadImagesAreNamedByTheCentrelinesPixelAhead) {
  EnvConfig c = datasetConfig(2);
  c.world = WorldConfig();
  c.camera.images = {"rgb"};
  TaskConfig t;
  t.task = TaskKind::kRoadFollowing;
  t.road.points = {0.0, 0.0, 3.0, 0.0};
  t.road.closed = false;
  t.road.start_offset = 0.0;
  t.road.start_yaw = 0.0;
  BatchedEnv env(cameraJetbot(), c, makeTask(t));
  const CameraModel model(env.camera()->intrinsics);
  // Straight ahead on a straight track: the middle column, below the horizon.
  const std::optional<Eigen::Vector2d> target = roadTarget(env, model, 0, 0.25);
  ASSERT_TRUE(target);
  EXPECT_NEAR(target->x(), 24.0, 0.5);
  // The camera looks 0.2 rad down from about 9 cm: 0.25 m ahead is below the image's centre,
  // 2 m ahead above it (towards the horizon, 0.2 rad above).
  EXPECT_GT(target->y(), 24.0);
  EXPECT_LT(roadTarget(env, model, 0, 2.0)->y(), 24.0);
  EXPECT_THROW(writeNotebookDataset(env,
                                    [] {
                                      DatasetOptions o;
                                      o.out = datasetDir("wrong_kind");
                                      return o;  // collision avoidance without depth and labels
                                    }()),
               ConfigError);
  DatasetOptions o;
  o.kind = DatasetKind::kRoadFollowing;
  o.out = datasetDir("road");
  o.count = 3;
  EXPECT_EQ(writeNotebookDataset(env, o).road, 3);
  int named = 0;
  for (const auto& f : std::filesystem::directory_iterator(o.out)) {
    const std::string name = f.path().filename().string();
    EXPECT_EQ(name.rfind("xy_02", 0), 0u) << name;  // x near the middle column, 24
    ++named;
  }
  EXPECT_EQ(named, 3);
}

}  // namespace
}  // namespace jetbot_rl
