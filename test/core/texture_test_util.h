#pragma once

// Fixtures of the texture tests: a red-and-blue texture, a world of one box in a material, and
// what the camera Jetbot sees of it.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace test {

/// A 2 x 1 texture: its left texel red, its right one blue; its path.
inline std::string redBlueTexture(const std::string& name) {
  return writePng(name, 2, 1, {255, 0, 0, 255, 0, 0, 255, 255});
}

/// A world of one 0.1 x 0.4 x 0.5 m box 0.35 m ahead whose material is `material` (SDF text).
inline std::string boxWorld(const std::string& name, const std::string& material) {
  return sdfWorld(
      name,
      "<model name=\"panel\"><static>true</static><pose>0.35 0 0.25 0 0 0</pose>"
      "<link name=\"link\"><collision name=\"c\"><geometry><box><size>0.1 0.4 0.5</size></box>"
      "</geometry></collision><visual name=\"v\"><geometry><box><size>0.1 0.4 0.5</size></box>"
      "</geometry>" +
          material + "</visual></link></model>\n");
}

/// The camera Jetbot at the origin facing +x, 33 x 33 px over 0.6 rad, seeing `world`'s model
/// (`env` keeps the batch).
inline EnvImages seenImages(const std::string& world, std::unique_ptr<BatchedEnv>& env) {
  EnvConfig c = smallConfig(1);
  c.world.gazebo_world = world;
  c.world.start_clearance = 0.1;
  c.camera.width = 33;
  c.camera.height = 33;
  c.camera.horizontal_fov = 0.6;
  c.camera.noise_std = 0.0;
  c.camera.images = {"rgb", "label"};
  env = std::make_unique<BatchedEnv>(
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf"), c);
  return env->view(0).images();
}

/// On the centre row of seenImages(), the surface ahead red left of the centre and blue right
/// of it (redBlueTexture() across it, as seen from the camera).
inline void expectRedLeftBlueRight(const EnvImages& images) {
  const int row = 16 * 33;
  for (int x : {12, 14, 18, 20}) {
    ASSERT_EQ(images.label[row + x], static_cast<std::uint8_t>(SurfaceClass::kMap)) << x;
    const std::uint8_t* rgb = images.rgb + 3 * (row + x);
    EXPECT_EQ(rgb[1], 0) << x;
    EXPECT_GT(x < 16 ? rgb[0] : rgb[2], 60) << x;
    EXPECT_EQ(x < 16 ? rgb[2] : rgb[0], 0) << x;
  }
}

}  // namespace test
}  // namespace jetbot_rl
