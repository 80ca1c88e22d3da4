// Published Gazebo worlds' quirks that Gazebo 11 loads (issue 48): a model URI with three slashes
// (ROBOTIS's turtlebot3_house.world) and a link whose inertia sdformat refuses (AWS's small
// house's shoe rack), in the world and in an included model folder.
#include <gtest/gtest.h>

#include <filesystem>

#include "gazebo_test_util.h"
#include "jetbot_rl/robot/package_path.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

using test::box;
using test::GazeboWorldTest;
using test::sdfWorld;
using test::solid;

TEST_F(GazeboWorldTest, AModelUriWithThreeSlashesIsFoundAsGazeboFindsIt) {
  // turtlebot3_house.world (ROBOTIS) names a mesh model:///table_marble/meshes/...: Gazebo 11
  // loads it, the slashes before the model's name counting for nothing.
  const auto counter = [](const std::string& uri) {
    return "<model name=\"counter\"><static>true</static><link name=\"body\"><collision "
           "name=\"collision\"><geometry><mesh><uri>" +
           uri +
           "</uri><scale>0.001 0.001 0.001</scale></mesh></geometry></collision></link>"
           "</model>\n";
  };
  const GazeboWorld two = loadGazeboWorld(
      sdfWorld("two.world", counter("model://jetbot_rl_counter/meshes/counter.stl")));
  const GazeboWorld three = loadGazeboWorld(
      sdfWorld("three.world", counter("model:///jetbot_rl_counter/meshes/counter.stl")));
  ASSERT_EQ(three.solids.size(), 1u);
  EXPECT_EQ(three.solids[0].triangles, two.solids[0].triangles);
  EXPECT_EQ(findGazeboModel("model:///jetbot_rl_counter/meshes/counter.stl"),
            findGazeboModel("model://jetbot_rl_counter/meshes/counter.stl"));
  EXPECT_EQ(findGazeboModel("model:///"), "");
}

TEST_F(GazeboWorldTest, ALinkWhoseInertiaSdformatRefusesIsReadWithoutIt) {
  // As aws-robomaker-small-house-world's shoe rack has it: <ixx> twice, no <izz> (so 1, more than
  // the other two together): sdformat refuses the link, and with it the world; Gazebo 11 loads.
  const std::string inertia =
      "<inertial><mass>6</mass><inertia><ixx>0.02</ixx><ixy>0</ixy><ixz>0</ixz><iyy>0.04</iyy>"
      "<iyz>0</iyz><ixx>0.02</ixx></inertia></inertial>";
  const auto rack = [&](const std::string& name, const std::string& pose) {
    return "<model name=\"" + name + "\"><pose>" + pose + "</pose><link name=\"link\">" + inertia +
           box("collision", "0 0 0.4 0 0 0", "0.8 0.3 0.8") + "</link></model>\n";
  };
  // The same as a model folder on GAZEBO_MODEL_PATH, included.
  const std::filesystem::path models = std::filesystem::path(::testing::TempDir()) / "rack_models";
  std::filesystem::create_directories(models / "shoe_rack");
  test::writeTempFile("rack_models/shoe_rack/model.config",
                      "<?xml version=\"1.0\"?><model><name>shoe_rack</name>"
                      "<sdf version=\"1.6\">model.sdf</sdf></model>\n");
  const std::string model_sdf = test::writeTempFile(
      "rack_models/shoe_rack/model.sdf", "<?xml version=\"1.0\"?>\n<sdf version=\"1.6\">\n" +
                                             rack("shoe_rack", "0 0 0 0 0 0") + "</sdf>\n");
  ::setenv("GAZEBO_MODEL_PATH",
           (models.string() + ":" + std::string(JETBOT_RL_SOURCE_DIR) + "/models").c_str(), 1);
  const std::string path =
      sdfWorld("racks.world",
               rack("hall_rack", "2 0 0 0 0 0") +
                   "<include><uri>model://shoe_rack</uri><pose>-2 0 0 0 0 0</pose></include>\n");
  const GazeboWorld world = loadGazeboWorld(path);
  ASSERT_EQ(world.solids.size(), 2u);
  EXPECT_NEAR(solid(world, "hall_rack::link::collision").bounds.center().x(), 2.0, 1e-9);
  EXPECT_NEAR(solid(world, "shoe_rack::link::collision").bounds.center().x(), -2.0, 1e-9);
  // One warning per link, naming its file, line and model.
  ASSERT_EQ(world.warnings.size(), 2u);
  std::string all;
  for (const std::string& w : world.warnings) all += w + "\n";
  EXPECT_NE(all.find(path + ":"), std::string::npos) << all;
  EXPECT_NE(all.find(model_sdf + ":"), std::string::npos) << all;
  EXPECT_NE(all.find("model 'hall_rack', link 'link'"), std::string::npos) << all;
  EXPECT_NE(all.find("model 'shoe_rack', link 'link'"), std::string::npos) << all;
  EXPECT_NE(all.find("an inertia sdformat refuses"), std::string::npos) << all;
}

}  // namespace
}  // namespace jetbot_rl
