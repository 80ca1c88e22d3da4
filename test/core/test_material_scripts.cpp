// Gazebo's material scripts (Ogre `.material` files) as a camera draws them: a material's
// diffuse colour, first texture and its scale, a parent's values inherited, comments and what is
// not followed skipped; scripts found through a visual's <uri>s, each file read once and bounded;
// a box with a script's texture seen as the script says, and a script or texture not found named.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "texture_test_util.h"
#include "world/gazebo/ogre_materials.h"

namespace jetbot_rl {
namespace {

TEST(MaterialScripts, TheFirstPassesColourAndTheFirstTextureUnitAreRead) {
  std::map<std::string, ScriptMaterial> m;
  parseMaterialScript(
      "// a comment { }\n"
      "material Wall/Brick\n{\n  receive_shadows off\n  technique\n  {\n    pass\n    {\n"
      "      ambient 0.1 0.1 0.1 1\n      diffuse 0.8 0.4 0.2 1.0 // warm\n"
      "      texture_unit\n      {\n        texture brick.png\n        scale 0.5 2\n      }\n"
      "      texture_unit\n      {\n        texture lightmap.png\n      }\n    }\n"
      "    pass\n    {\n      diffuse 0 0 0 1\n    }\n  }\n}\n"
      "material Wall/Dark : Wall/Brick\n{\n  technique { pass { diffuse 0.1 0.1 0.1 } }\n}\n"
      "material Plain/Blue { technique { pass { diffuse 0 0 1 texture_unit { } } } }\n"
      "material Odd/Values { technique { pass { diffuse a b c\n texture_unit {\n scale 0 1 } } } "
      "}\n",
      m);
  ASSERT_EQ(m.size(), 4u);
  const ScriptMaterial& brick = m.at("Wall/Brick");
  ASSERT_TRUE(brick.diffuse);
  EXPECT_TRUE(brick.diffuse->isApprox(Eigen::Vector3f(0.8f, 0.4f, 0.2f)));
  EXPECT_EQ(brick.texture, "brick.png");
  EXPECT_TRUE(brick.scale.isApprox(Eigen::Vector2f(0.5f, 2.0f)));
  const ScriptMaterial& dark = m.at("Wall/Dark");  // its parent's texture, its own colour
  EXPECT_TRUE(dark.diffuse->isApprox(Eigen::Vector3f(0.1f, 0.1f, 0.1f)));
  EXPECT_EQ(dark.texture, "brick.png");
  EXPECT_TRUE(m.at("Plain/Blue").texture.empty());
  EXPECT_TRUE(m.at("Plain/Blue").diffuse->isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_FALSE(m.at("Odd/Values").diffuse);                               // not numbers: not read
  EXPECT_TRUE(m.at("Odd/Values").scale.isApprox(Eigen::Vector2f(1, 1)));  // a 0 scale: not read
}

TEST(MaterialScripts, FoldersAreReadOnceAndBounded) {
  const std::string folder = ::testing::TempDir() + "script_folder";
  ::mkdir(folder.c_str(), 0755);
  test::writeTempFile("script_folder/a.material",
                      "material A/One { technique { pass { diffuse 1 0 0 } } }\n");
  test::writeTempFile("script_folder/big.material",
                      std::string(ScriptMaterials::kMaxScriptBytes + 1, ' '));
  ScriptMaterials scripts;
  std::vector<std::string> problems;
  ASSERT_TRUE(scripts.find("A/One", {folder}, problems));
  EXPECT_FALSE(scripts.find("A/Two", {folder}, problems));
  ASSERT_EQ(problems.size(), 1u);  // once, though the folder was asked twice
  EXPECT_EQ(problems[0], "material script '" + folder + "/big.material' (over 1048576 bytes)");
  EXPECT_FALSE(scripts.find("A/One", {folder + "/none.material"}, problems));
  EXPECT_NE(problems.back().find("does not exist"), std::string::npos) << problems.back();
  // In all, at most kMaxScriptTotalBytes are read: after a.material, 63 files of 1 MiB fit.
  const std::string many = ::testing::TempDir() + "script_many";
  ::mkdir(many.c_str(), 0755);
  std::vector<std::string> written;
  for (int i = 0; i < 64; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "/%02d.material", i);
    // Each exactly kMaxScriptBytes: the last one passes the total by a.material's bytes.
    const std::string text =
        "material M/" + std::to_string(i) + " { technique { pass { diffuse 0 0 1 } } }\n";
    written.push_back(test::writeTempFile(
        "script_many" + std::string(name),
        text + std::string(ScriptMaterials::kMaxScriptBytes - text.size(), ' ')));
  }
  problems.clear();
  EXPECT_TRUE(scripts.find("M/62", {many}, problems));
  EXPECT_FALSE(scripts.find("M/63", {many}, problems));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "material script '" + many +
                             "/63.material' (beyond the 67108864 bytes "
                             "of scripts read)");
  for (const std::string& w : written) std::remove(w.c_str());
}

/// A world of the box of test::boxWorld() whose visual's material is `script`, found in `uri`.
std::string scriptWorld(const std::string& name, const std::string& script,
                        const std::string& uri) {
  return test::boxWorld(name, "<material><script><uri>" + uri + "</uri><name>" + script +
                                  "</name></script></material>");
}

TEST(MaterialScripts, TheCameraSeesABoxInItsScriptsTexture) {
  // Gazebo's layout: materials/scripts/x.material naming a texture in materials/textures/.
  const std::string model = ::testing::TempDir() + "script_model";
  for (const std::string& d : {"", "/materials", "/materials/scripts", "/materials/textures"}) {
    ::mkdir((model + d).c_str(), 0755);
  }
  test::writeTempFile("script_model/materials/scripts/panel.material",
                      "material Panel/RedBlue\n{\n technique\n {\n  pass\n  {\n   texture_unit\n"
                      "   {\n    texture red_blue.png\n   }\n  }\n }\n}\n");
  test::redBlueTexture("script_model/materials/textures/red_blue.png");
  const std::string world =
      scriptWorld("script_panel.world", "Panel/RedBlue", "file://" + model + "/materials/scripts");
  const GazeboWorld read = loadGazeboWorld(world, nullptr, true);
  ASSERT_EQ(read.visuals.size(), 1u);
  ASSERT_TRUE(read.visuals[0].texture);
  EXPECT_EQ(read.visuals[0].texture->path, model + "/materials/textures/red_blue.png");
  EXPECT_EQ(read.visuals[0].uv.size(), read.visuals[0].triangles.size());
  EXPECT_TRUE(read.skipped.empty()) << read.skipped;

  std::unique_ptr<BatchedEnv> env;
  // The face towards the camera: along its horizontal edge, red on the +y half (the image's
  // left), blue on the other.
  test::expectRedLeftBlueRight(test::seenImages(world, env));
}

TEST(MaterialScripts, AScriptOrTextureNotFoundIsNamed) {
  const std::string folder = ::testing::TempDir() + "script_lost";
  ::mkdir(folder.c_str(), 0755);
  test::writeTempFile("script_lost/lost.material",
                      "material Lost/Texture { technique { pass { diffuse 0 1 0\n"
                      "texture_unit { texture nowhere.png } } } }\n");
  const GazeboWorld read = loadGazeboWorld(
      scriptWorld("script_lost.world", "Lost/Texture", "file://" + folder), nullptr, true);
  ASSERT_EQ(read.visuals.size(), 1u);
  EXPECT_FALSE(read.visuals[0].texture);
  EXPECT_TRUE(read.visuals[0].colour.isApprox(Eigen::Vector3f(0, 1, 0)));  // the script's colour
  EXPECT_NE(read.skipped.find("texture 'nowhere.png' of material 'Lost/Texture' of visual "
                              "'panel::link::v' (not found; its colour drawn)"),
            std::string::npos)
      << read.skipped;
  const GazeboWorld unknown = loadGazeboWorld(
      scriptWorld("script_unknown.world", "No/Such", "file://" + folder), nullptr, true);
  EXPECT_NE(unknown.skipped.find("material 'No/Such' of visual 'panel::link::v' (drawn grey)"),
            std::string::npos)
      << unknown.skipped;
}

}  // namespace
}  // namespace jetbot_rl
