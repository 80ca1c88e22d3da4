#pragma once

// Fixtures of the Gazebo world tests: the package's models on GAZEBO_MODEL_PATH, SDF snippets of
// static models and their collisions, a solid found by its scoped name.

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {
namespace test {

/// The package's models found as Gazebo finds them, through GAZEBO_MODEL_PATH.
class GazeboWorldTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ::setenv("GAZEBO_MODEL_PATH", (std::string(JETBOT_RL_SOURCE_DIR) + "/models").c_str(), 1);
    ::unsetenv("ROS_PACKAGE_PATH");
  }
};

/// The solid scoped `name` of `world` (std::runtime_error if none).
inline const WorldSolid& solid(const GazeboWorld& world, const std::string& name) {
  for (const WorldSolid& s : world.solids) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no solid " + name);
}

/// A static model `name` at `pose` with one link, `link`, holding `collisions`.
inline std::string staticModel(const std::string& name, const std::string& pose,
                               const std::string& collisions) {
  return "<model name=\"" + name + "\"><static>true</static><pose>" + pose +
         "</pose><link name=\"link\">" + collisions + "</link></model>\n";
}

/// A box collision `name` at `pose` of `size` ("x y z").
inline std::string box(const std::string& name, const std::string& pose, const std::string& size) {
  return "<collision name=\"" + name + "\"><pose>" + pose + "</pose><geometry><box><size>" + size +
         "</size></box></geometry></collision>";
}

/// A cylinder collision `name` at `pose`.
inline std::string cylinder(const std::string& name, const std::string& pose, double radius,
                            double length) {
  return "<collision name=\"" + name + "\"><pose>" + pose + "</pose><geometry><cylinder><radius>" +
         std::to_string(radius) + "</radius><length>" + std::to_string(length) +
         "</length></cylinder></geometry></collision>";
}

}  // namespace test
}  // namespace jetbot_rl
