// A Gazebo world as cameras see it: its <visual> elements read with their materials (a diffuse
// colour, a Gazebo script's colour, an unknown script noted) only when a camera asks for them,
// bad visuals named with their file and line, and a camera seeing a model in its colour (in the
// map's colour without world visuals).
#include <gtest/gtest.h>

#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

/// A model `name` at (x, y) with a link holding `collision` and `visual` (SDF text).
std::string gazeboModel(const std::string& name, double x, double y, const std::string& collision,
                        const std::string& visual) {
  return "<model name=\"" + name + "\"><static>true</static><pose>" + std::to_string(x) + " " +
         std::to_string(y) + " 0.25 0 0 0</pose><link name=\"link\">" + collision + visual +
         "</link></model>\n";
}

std::string boxCollision() {
  return "<collision name=\"c\"><geometry><box><size>0.4 0.4 0.5</size></box></geometry>"
         "</collision>";
}

std::string boxVisual(const std::string& size, const std::string& material) {
  return "<visual name=\"v\"><geometry><box><size>" + size + "</size></box></geometry>" + material +
         "</visual>";
}

/// A red box 0.3 m ahead of the origin, a wooden one and a cylinder of a script no one knows.
std::string colouredWorld() {
  return test::sdfWorld(
      "coloured.world",
      gazeboModel("red_box", 0.5, 0.0, boxCollision(),
                  boxVisual("0.4 0.4 0.5", "<material><diffuse>1 0 0 1</diffuse></material>")) +
          gazeboModel("wooden_box", -1.0, 1.0, boxCollision(),
                      boxVisual("0.4 0.4 0.5",
                                "<material><script><uri>file://media/materials/scripts/"
                                "gazebo.material</uri><name>Gazebo/Wood</name></script>"
                                "</material>")) +
          gazeboModel("odd", -1.0, -1.0, boxCollision(),
                      "<visual name=\"v\"><geometry><cylinder><radius>0.2</radius><length>0.5"
                      "</length></cylinder></geometry><material><script><uri>file://custom.material"
                      "</uri><name>Custom/Thing</name></script></material></visual>"));
}

TEST(CameraGazebo, VisualsAreReadWithTheirMaterialsWhenAsked) {
  const std::string path = colouredWorld();
  EXPECT_TRUE(loadGazeboWorld(path).visuals.empty());  // no camera: not read
  const GazeboWorld world = loadGazeboWorld(path, nullptr, true);
  ASSERT_EQ(world.visuals.size(), 3u);
  EXPECT_EQ(world.visuals[0].name, "red_box::link::v");
  EXPECT_TRUE(world.visuals[0].colour.isApprox(Eigen::Vector3f(1.0f, 0.0f, 0.0f)));
  EXPECT_TRUE(world.visuals[1].colour.isApprox(Eigen::Vector3f(0.52f, 0.37f, 0.26f)));
  EXPECT_TRUE(world.visuals[2].colour.isApprox(Eigen::Vector3f(0.7f, 0.7f, 0.7f)));
  EXPECT_NE(world.skipped.find("material 'Custom/Thing' of visual 'odd::link::v' (drawn grey)"),
            std::string::npos)
      << world.skipped;
  // Placed in the world: the red box's corners within 0.2 m of x = 0.5.
  for (const Eigen::Vector3d& c : world.visuals[0].triangles) {
    EXPECT_NEAR(c.x(), 0.5, 0.2 + 1e-9);
    EXPECT_NEAR(c.z(), 0.25, 0.25 + 1e-9);
  }
}

TEST(CameraGazebo, BadVisualsAreNamedWithTheirFileAndLine) {
  const std::string path = test::sdfWorld(
      "bad_visual.world", gazeboModel("flat", 0.0, 0.0, boxCollision(), boxVisual("0 1 1", "")));
  EXPECT_NO_THROW(loadGazeboWorld(path));  // visuals not read: nothing to refuse
  try {
    loadGazeboWorld(path, nullptr, true);
    ADD_FAILURE() << "a visual box of size 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("visual 'flat::link::v': its box size 0"),
              std::string::npos)
        << e.what();
  }
  const std::string mesh = test::sdfWorld(
      "missing_mesh.world",
      gazeboModel("m", 1.5, 0.0, boxCollision(),
                  "<visual name=\"v\"><geometry><mesh><uri>model://no_such_model/m.dae</uri>"
                  "</mesh></geometry></visual>"));
  EnvConfig c = test::smallConfig(1);
  c.world.gazebo_world = mesh;
  c.world.spawn = {1.5, 0.7};  // in the world's grid, clear of the model
  c.camera.width = 8;
  c.camera.height = 8;
  try {
    BatchedEnv env(
        RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf"),
        c);
    ADD_FAILURE() << "a visual mesh that cannot be found accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("visual 'm::link::v'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("camera/world_visuals"), std::string::npos) << e.what();
  }
  c.camera.world_visuals = false;
  EXPECT_NO_THROW(BatchedEnv(
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf"), c));
}

TEST(CameraGazebo, TheCameraSeesAModelInItsColour) {
  // The camera Jetbot at the origin facing +x: the red box, 0.3 m ahead, is where its camera's
  // axis (pitched down 0.2 rad) meets it.
  EnvConfig c = test::smallConfig(1);
  c.world.gazebo_world = colouredWorld();
  c.world.start_clearance = 0.2;
  c.camera.width = 33;
  c.camera.height = 33;
  c.camera.horizontal_fov = 0.6;
  c.camera.noise_std = 0.0;
  c.camera.images = {"rgb", "label"};
  const RobotModelConstPtr robot =
      RobotModel::fromUrdfFile(std::string(JETBOT_RL_SOURCE_DIR) + "/urdf/jetbot_camera.urdf");
  const int centre = 16 * 33 + 16;
  BatchedEnv seen(robot, c);
  EnvImages images = seen.view(0).images();
  ASSERT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kMap));
  const std::uint8_t* rgb = images.rgb + 3 * centre;
  EXPECT_GT(rgb[0], 60);
  EXPECT_EQ(rgb[1], 0);
  EXPECT_EQ(rgb[2], 0);
  c.camera.world_visuals = false;  // the shapes the scanner sees, in the map's colour
  BatchedEnv plain(robot, c);
  images = plain.view(0).images();
  ASSERT_EQ(images.label[centre], static_cast<std::uint8_t>(SurfaceClass::kMap));
  rgb = images.rgb + 3 * centre;
  EXPECT_GT(rgb[1], 60);
  EXPECT_GT(rgb[2], 60);
}

}  // namespace
}  // namespace jetbot_rl
