#pragma once
// What the camera's tests share: the camera Jetbot, intrinsics, upright boxes, and images compared
// bit for bit.

#include <gtest/gtest.h>

#include <cstring>

#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/world/world_model.h"
#include "test_util.h"

namespace jetbot_rl {

/// urdf/jetbot_camera.urdf: the Jetbot with its IMX219 camera block, loaded once.
inline RobotModelConstPtr cameraJetbot() {
  static const RobotModelConstPtr model =
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf");
  return model;
}

/// Intrinsics of `width` x `height` px, horizontal fov `fov` [rad], clip [0.05, 20] m.
inline CameraIntrinsics cameraIntrinsics(int width, int height, double fov) {
  CameraIntrinsics c;
  c.width = width;
  c.height = height;
  c.horizontal_fov = fov;
  c.near = 0.05;
  c.far = 20.0;
  return c;
}

/// A box standing on the ground at (x, y) [m], half extents hx, hy [m], `height` [m] tall.
inline Obstacle standingBox(double x, double y, double hx, double hy, double height) {
  Obstacle o;
  o.center = {x, y};
  o.half_extents = {hx, hy};
  o.height = height;
  return o;
}

/// `a` and `b` the same: rgb and labels equal, depth equal bit for bit (NaN and infinities too).
inline void expectSameImages(const CameraImages& a, const CameraImages& b) {
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.label, b.label);
  ASSERT_EQ(a.depth.size(), b.depth.size());
  EXPECT_EQ(0, std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)));
}

/// A batch of camera robots in a 3 x 3 m arena with two boxes each, 32 x 24 images of every kind.
inline EnvConfig cameraArenaConfig(int num_envs, int threads) {
  EnvConfig c = test::smallConfig(num_envs, threads);
  c.world.arena_size = {3.0, 3.0};
  c.world.num_boxes = 2;
  c.world.random_start = true;
  c.camera.width = 32;
  c.camera.height = 24;
  c.camera.images = {"rgb", "depth", "label"};
  return c;
}

}  // namespace jetbot_rl
