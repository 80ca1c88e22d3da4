// A mesh's own materials as a camera sees them: a visual mesh without a <material> shows each
// part of its file in that part's diffuse colour or texture (as Gazebo draws it), a <material>
// still colours the whole mesh, a texture that cannot be read is named and its colour drawn, and
// a texture is sampled where its coordinates say.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/texture_image.h"
#include "sensors/camera_robot.h"
#include "texture_test_util.h"

namespace jetbot_rl {
namespace {

/// An OBJ of two parts: an upright 0.4 x 0.5 m quad facing -x at x = -0.05 (its texture's left
/// half at +y, where a camera looking along +x sees its left), of material `textured`, and a
/// green triangle behind it, below the camera's view. Its path.
std::string texturedMesh(const std::string& stem, const std::string& texture) {
  test::writeTempFile(stem + ".mtl", "newmtl textured\nKd 0.5 0.5 0.5\nmap_Kd " + texture +
                                         "\nnewmtl green\nKd 0 1 0\n");
  return test::writeTempFile(stem + ".obj",
                             "mtllib " + stem +
                                 ".mtl\n"
                                 "v -0.05 0.2 -0.25\nv -0.05 -0.2 -0.25\nv -0.05 -0.2 0.25\n"
                                 "v -0.05 0.2 0.25\nv 0.1 0 -0.25\nv 0.1 0.1 -0.25\nv 0.1 0 -0.2\n"
                                 "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                 "usemtl textured\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"
                                 "usemtl green\nf 5 6 7\n");
}

/// A world of one static model 0.35 m ahead of the origin whose visual is `mesh` with
/// `material` (SDF text, may be empty); its path.
std::string meshWorld(const std::string& name, const std::string& mesh,
                      const std::string& material) {
  return test::sdfWorld(
      name,
      "<model name=\"poster\"><static>true</static><pose>0.35 0 0.25 0 0 0</pose>"
      "<link name=\"link\"><collision name=\"c\"><geometry><box><size>0.05 0.4 0.5</size></box>"
      "</geometry></collision><visual name=\"v\"><geometry><mesh><uri>" +
          mesh + "</uri></mesh></geometry>" + material + "</visual></link></model>\n");
}

TEST(MeshMaterials, EachPartHasItsColourAndTexture) {
  const std::string mesh = texturedMesh("parts_mesh", "parts_texture.png");
  test::redBlueTexture("parts_texture.png");
  const std::vector<MeshPart> parts = loadMeshParts(mesh);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].triangles.size(), 6u);
  EXPECT_EQ(parts[0].texture, ::testing::TempDir() + "parts_texture.png");
  EXPECT_EQ(parts[0].texture_as_given, "parts_texture.png");
  ASSERT_EQ(parts[0].uv.size(), 6u);
  EXPECT_TRUE(parts[0].uv[1].isApprox(Eigen::Vector2f(1.0f, 0.0f)));
  EXPECT_EQ(parts[1].triangles.size(), 3u);
  ASSERT_TRUE(parts[1].colour);
  EXPECT_TRUE(parts[1].colour->isApprox(Eigen::Vector3f(0.0f, 1.0f, 0.0f)));
  EXPECT_TRUE(parts[1].texture.empty());
  EXPECT_EQ(parts[1].uv.size(), 3u);  // for a script's texture
  // A file naming no material: one part, no colour (grey is the reader's).
  const std::string plain = test::writeTempFile(
      "plain_mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
  const std::vector<MeshPart> one = loadMeshParts(plain);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_FALSE(one[0].colour);
  EXPECT_TRUE(one[0].triangles == loadMeshTriangles(plain));
}

TEST(MeshMaterials, ATextureIsFoundInTheModelsTextureFolderAsGazeboFindsIt) {
  const std::string model = ::testing::TempDir() + "texture_folder_model";
  ::mkdir(model.c_str(), 0755);
  ::mkdir((model + "/meshes").c_str(), 0755);
  ::mkdir((model + "/materials").c_str(), 0755);
  ::mkdir((model + "/materials/textures").c_str(), 0755);
  test::redBlueTexture("texture_folder_model/materials/textures/wall.png");
  const std::string mesh =
      texturedMesh("texture_folder_model/meshes/wall", "some/where/else/wall.png");
  const std::vector<MeshPart> parts = loadMeshParts(mesh);
  ASSERT_FALSE(parts.empty());
  EXPECT_EQ(parts[0].texture, model + "/materials/textures/wall.png");
}

TEST(TextureImage, CoordinatesRepeatWithVUp) {
  // 2 x 2: top row red, green; bottom row blue, white.
  const std::string path =
      test::writePng("texture_2x2.png", 2, 2,
                     {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255});
  const auto t = loadTextureImage(path);
  ASSERT_EQ(t->width, 2);
  ASSERT_EQ(t->height, 2);
  EXPECT_TRUE(t->at(0.25f, 0.75f).isApprox(Eigen::Vector3f(1, 0, 0)));  // top left
  EXPECT_TRUE(t->at(0.75f, 0.75f).isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_TRUE(t->at(0.25f, 0.25f).isApprox(Eigen::Vector3f(0, 0, 1)));   // bottom left
  EXPECT_TRUE(t->at(1.75f, -0.75f).isApprox(Eigen::Vector3f(1, 1, 1)));  // repeated
  EXPECT_TRUE(t->at(1.0f, 1.0f).isApprox(Eigen::Vector3f(0, 0, 1)));     // wraps to (0, 0)
  EXPECT_TRUE(t->at(std::nanf(""), 0.5f).isApprox(Eigen::Vector3f(1, 0, 0)));
}

TEST(TextureImage, FilesItCannotUseAreNamed) {
  const auto refused = [](const std::string& path, const std::string& why) {
    try {
      loadTextureImage(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find("texture '" + path + "' " + why), std::string::npos)
          << e.what();
    }
  };
  refused(::testing::TempDir() + "no_such_texture.png", "does not exist");
  const std::string fifo = ::testing::TempDir() + "texture_fifo.png";
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  refused(fifo, "is a FIFO");  // never opened: it would block
  refused(test::writeTempFile("not_a_texture.png", "text"), "cannot be read as an image");
  refused(test::writePng("wide_texture.png", kMaxTextureSide + 1, 1,
                         std::vector<unsigned char>(4 * (kMaxTextureSide + 1), 255)),
          "is 8193 x 1 px: at most 8192 px a side");
  // The textures of a world or robot, counted: one more past the budget is refused.
  const std::string small = test::redBlueTexture("budget_texture.png");
  std::size_t bytes = kMaxTextureBytes - 6;
  ASSERT_TRUE(loadTextureImage(small, &bytes));
  EXPECT_EQ(bytes, kMaxTextureBytes);
  try {
    loadTextureImage(small, &bytes);
    ADD_FAILURE() << "a texture past the budget accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("would make 1025 MiB of textures, more than the 1024 MiB "
                                         "allowed"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(bytes, kMaxTextureBytes);  // nothing counted
}

TEST(CameraTextures, TheCameraSeesAMeshsTextureWhereItsCoordinatesPutIt) {
  const std::string mesh = texturedMesh("seen_mesh", "seen_texture.png");
  test::redBlueTexture("seen_texture.png");
  const GazeboWorld read = loadGazeboWorld(meshWorld("textured.world", mesh, ""), nullptr, true);
  ASSERT_EQ(read.visuals.size(), 2u);  // one per part of the file
  ASSERT_TRUE(read.visuals[0].texture);
  EXPECT_EQ(read.visuals[0].uv.size(), read.visuals[0].triangles.size());
  EXPECT_FALSE(read.visuals[1].texture);
  EXPECT_TRUE(read.visuals[1].colour.isApprox(Eigen::Vector3f(0, 1, 0)));

  std::unique_ptr<BatchedEnv> env;
  const EnvImages images = test::seenImages(meshWorld("textured.world", mesh, ""), env);
  // The centre row: left of the centre the texture's red half, right of it its blue half.
  test::expectRedLeftBlueRight(images);  // the texture's red half left of the centre
  // A <material> colours the whole mesh, as before.
  std::unique_ptr<BatchedEnv> coloured;
  const EnvImages green = test::seenImages(
      meshWorld("coloured_mesh.world", mesh, "<material><diffuse>0 1 0 1</diffuse></material>"),
      coloured);
  for (int x : {12 + 16 * 33, 20 + 16 * 33}) {  // the centre row
    const std::uint8_t* rgb = green.rgb + 3 * x;
    EXPECT_EQ(rgb[0], 0) << x;
    EXPECT_GT(rgb[1], 60) << x;
    EXPECT_EQ(rgb[2], 0) << x;
  }
}

TEST(CameraTextures, ATextureThatCannotBeReadIsNamedAndItsColourDrawn) {
  const std::string mesh = texturedMesh("unread_mesh", "unread_texture.png");
  test::writeTempFile("unread_texture.png", "no image");
  const GazeboWorld read = loadGazeboWorld(meshWorld("unread.world", mesh, ""), nullptr, true);
  ASSERT_EQ(read.visuals.size(), 2u);
  EXPECT_FALSE(read.visuals[0].texture);
  EXPECT_TRUE(read.visuals[0].uv.empty());
  EXPECT_TRUE(read.visuals[0].colour.isApprox(Eigen::Vector3f(0.5f, 0.5f, 0.5f)));
  EXPECT_NE(read.skipped.find("texture '" + ::testing::TempDir() +
                              "unread_texture.png' cannot be read as an image"),
            std::string::npos)
      << read.skipped;
  EXPECT_NE(read.skipped.find("of visual 'poster::link::v' (its colour drawn)"), std::string::npos)
      << read.skipped;
  const std::string lost = texturedMesh("lost_mesh", "lost_texture.png");
  const GazeboWorld missing = loadGazeboWorld(meshWorld("lost.world", lost, ""), nullptr, true);
  EXPECT_NE(missing.skipped.find(
                "texture 'lost_texture.png' of visual 'poster::link::v' (not found; its colour "
                "drawn)"),
            std::string::npos)
      << missing.skipped;
}

TEST(CameraTextures, ARobotsMeshWithoutAURDFColourShowsItsOwnMaterials) {
  VisualGeometry v;
  v.link = "shell";
  v.shape.type = CollisionGeometry::Type::kMesh;
  v.shape.size = Eigen::Vector3d(2.0, 1.0, 1.0);  // the mesh's scale
  v.shape.mesh_uri = "file://robot_mesh.obj";
  v.mesh_path = texturedMesh("robot_mesh", "robot_texture.png");
  test::redBlueTexture("robot_texture.png");
  TextureCache textures;
  const auto surfaces = visualSurfaces(v, textures);
  ASSERT_EQ(surfaces.size(), 2u);
  ASSERT_TRUE(surfaces[0].first.texture);
  EXPECT_EQ(surfaces[0].first.uv.size(), surfaces[0].second.size());
  EXPECT_TRUE(surfaces[0].first.at(0, 0.0f, 0.0f).isApprox(Eigen::Vector3f(1, 0, 0)));  // u 0
  EXPECT_TRUE(surfaces[0].first.at(0, 0.9f, 0.0f).isApprox(Eigen::Vector3f(0, 0, 1)));  // u 0.9
  EXPECT_TRUE(surfaces[1].first.colour.isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_NEAR(surfaces[1].second[0].x(), 0.2, 1e-6);  // scaled
  EXPECT_EQ(textures.images.size(), 1u);
  EXPECT_EQ(textures.bytes, 6u);
  // A URDF colour colours the whole mesh.
  v.coloured = true;
  v.colour = Eigen::Vector3f(0.0f, 0.0f, 1.0f);
  const auto coloured = visualSurfaces(v, textures);
  ASSERT_EQ(coloured.size(), 1u);
  EXPECT_FALSE(coloured[0].first.texture);
  EXPECT_EQ(coloured[0].second.size(), 9u);
  // A texture the file names and nothing holds: the camera cannot draw the robot as it is.
  v.coloured = false;
  v.mesh_path = texturedMesh("robot_lost_mesh", "robot_lost_texture.png");
  try {
    visualSurfaces(v, textures);
    ADD_FAILURE() << "a missing texture accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()),
              "link 'shell': visual mesh 'file://robot_mesh.obj': texture 'robot_lost_texture.png' "
              "not found");
  }
}

TEST(CameraTextures, AnSdfPbrAlbedoMapCoversABox) {
  test::redBlueTexture("albedo_red_blue.png");  // beside the world file: a relative name
  const std::string pbr =
      "<material><diffuse>0 1 0 1</diffuse><pbr><metal><albedo_map>albedo_red_blue.png"
      "</albedo_map></metal></pbr></material>";
  const std::string world = test::boxWorld("albedo.world", pbr);
  const GazeboWorld read = loadGazeboWorld(world, nullptr, true);
  ASSERT_EQ(read.visuals.size(), 1u);
  ASSERT_TRUE(read.visuals[0].texture);
  EXPECT_EQ(read.visuals[0].texture->path, ::testing::TempDir() + "albedo_red_blue.png");
  std::unique_ptr<BatchedEnv> env;
  const EnvImages images = test::seenImages(world, env);
  test::expectRedLeftBlueRight(images);  // as a script's texture
  // A map that does not exist: named, the diffuse colour drawn.
  const GazeboWorld lost = loadGazeboWorld(
      test::boxWorld("albedo_lost.world", test::replaceOnce(pbr, "albedo_red_blue", "albedo_lost")),
      nullptr, true);
  ASSERT_EQ(lost.visuals.size(), 1u);
  EXPECT_FALSE(lost.visuals[0].texture);
  EXPECT_TRUE(lost.visuals[0].colour.isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_NE(lost.skipped.find("albedo_lost.png' does not exist of visual 'panel::link::v' (its "
                              "colour drawn)"),
            std::string::npos)
      << lost.skipped;
}

TEST(CameraTextures, AURDFTextureCoversABoxAcrossItsFaces) {
  const std::string texture = test::redBlueTexture("urdf_texture.png");
  const std::string green =
      "<material name=\"jetbot_green\"><color rgba=\"0.46 0.73 0.0 1.0\"/></material>";
  const RobotModelConstPtr robot = RobotModel::fromUrdfString(test::replaceOnce(
      test::jetbotUrdfText(), green,
      "<material name=\"decal\"><texture filename=\"" + texture + "\"/></material>"));
  const VisualGeometry* chassis = nullptr;
  for (const VisualGeometry& v : robot->bodies()[0].visuals) {
    if (v.shape.type == CollisionGeometry::Type::kBox) chassis = &v;
  }
  ASSERT_TRUE(chassis);
  EXPECT_EQ(chassis->texture_path, texture);
  TextureCache textures;
  const auto surfaces = visualSurfaces(*chassis, textures);
  ASSERT_EQ(surfaces.size(), 1u);
  ASSERT_TRUE(surfaces[0].first.texture);
  ASSERT_EQ(surfaces[0].first.uv.size(), surfaces[0].second.size());
  int left = 0, right = 0;  // of the corners of the faces' triangles
  for (const Eigen::Vector2f& uv : surfaces[0].first.uv) {
    EXPECT_TRUE(uv.x() >= -1e-6f && uv.x() <= 1.0f + 1e-6f && uv.y() >= -1e-6f &&
                uv.y() <= 1.0f + 1e-6f)
        << uv.transpose();
    (uv.x() < 0.5f ? left : right) += 1;
  }
  EXPECT_GT(left, 0);
  EXPECT_GT(right, 0);
  // A texture no file holds: the camera refuses naming the link and the texture.
  const RobotModelConstPtr lost = RobotModel::fromUrdfString(test::replaceOnce(
      test::jetbotUrdfText(), green,
      "<material name=\"decal\"><texture filename=\"package://no_such_package/t.png\"/>"
      "</material>"));
  for (const VisualGeometry& v : lost->bodies()[0].visuals) {
    if (v.shape.type != CollisionGeometry::Type::kBox) continue;
    try {
      visualSurfaces(v, textures);
      ADD_FAILURE() << "a texture that cannot be resolved accepted";
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find("base_link"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("visual texture 'package://no_such_package/t.png'"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace jetbot_rl
