// map_server's map YAML and image, read as map_server reads them: each mode, negate, alpha, the
// origin's pose, and bad files named.
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/world/occupancy_map.h"
#include "jetbot_rl/world/world_model.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

std::string loadError(const std::string& yaml) {
  try {
    OccupancyMap::fromYamlFile(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << yaml;
  return "";
}

TEST(OccupancyMap, TrinaryCellsFromTheLowerLeftAsMapServerServesThem) {
  const std::string pgm = test::writePgm("tri.pgm", {"#..", ".?.", "..#"});
  const OccupancyMap map = OccupancyMap::fromYamlFile(test::writeMapYaml("tri.yaml", "tri.pgm"));
  ASSERT_EQ(map.width, 3);
  ASSERT_EQ(map.height, 3);
  EXPECT_EQ(map.image_path, pgm);  // relative to the YAML's folder
  // Row 0 is the image's bottom row.
  EXPECT_EQ(map.at(2, 0), 100);
  EXPECT_EQ(map.at(0, 0), 0);
  EXPECT_EQ(map.at(1, 1), -1);
  EXPECT_EQ(map.at(0, 2), 100);
  EXPECT_TRUE(map.isObstacle(0, 2));
  EXPECT_TRUE(map.isFree(1, 2));
  EXPECT_FALSE(map.isFree(1, 1));
  EXPECT_FALSE(map.isObstacle(1, 1));
}

TEST(OccupancyMap, NegateSwapsBlackAndWhite) {
  test::writePgm("neg.pgm", {"#."});
  const OccupancyMap map = OccupancyMap::fromYamlFile(
      test::writeMapYaml("neg.yaml", "neg.pgm",
                         "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: "
                         "0.65\nfree_thresh: 0.196\n"));
  EXPECT_EQ(map.at(0, 0), 0);    // black, negated: free
  EXPECT_EQ(map.at(1, 0), 100);  // white, negated: occupied
}

TEST(OccupancyMap, ScaleModeGivesTheRatioBetweenTheThresholds) {
  test::writePgm("scale.pgm", {"5#."});
  const OccupancyMap map = OccupancyMap::fromYamlFile(test::writeMapYaml(
      "scale.yaml", "scale.pgm",
      "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
      "mode: scale\n"));
  const double occ = (255.0 - 125.0) / 255.0;
  const int expected = static_cast<int>(1 + 98 * (occ - 0.196) / (0.65 - 0.196));
  EXPECT_EQ(map.at(0, 0), expected);
  EXPECT_EQ(map.at(1, 0), 100);
  EXPECT_EQ(map.at(2, 0), 0);
}

TEST(OccupancyMap, RawModeKeepsThePixelValue) {
  test::writePgm("raw.pgm", {"04."});
  const OccupancyMap map = OccupancyMap::fromYamlFile(test::writeMapYaml(
      "raw.yaml", "raw.pgm",
      "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
      "mode: raw\n"));
  EXPECT_EQ(map.at(0, 0), 0);
  EXPECT_EQ(map.at(1, 0), 100);
  EXPECT_EQ(map.at(2, 0), static_cast<std::int8_t>(254));  // int8, as map_server stores it
  EXPECT_TRUE(map.isFree(0, 0));
  EXPECT_TRUE(map.isObstacle(1, 0));
  EXPECT_TRUE(map.isObstacle(2, 0));
}

TEST(OccupancyMap, PngAlphaIsUnknownInScaleModeAndAveragedInTrinaryMode) {
  // A transparent white pixel and an opaque black one.
  test::writePng("alpha.png", 2, 1, {255, 255, 255, 0, 0, 0, 0, 255});
  const std::string fields =
      "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const OccupancyMap scale = OccupancyMap::fromYamlFile(
      test::writeMapYaml("alpha_scale.yaml", "alpha.png", fields + "mode: scale\n"));
  EXPECT_EQ(scale.at(0, 0), 0);    // white: free whatever its alpha
  EXPECT_EQ(scale.at(1, 0), 100);  // black
  // Trinary mode averages the alpha channel with the colours (map_server's image_loader):
  // transparent white (255 + 255 + 255 + 0) / 4 = 191: occupancy 0.25, unknown.
  const OccupancyMap trinary =
      OccupancyMap::fromYamlFile(test::writeMapYaml("alpha_tri.yaml", "alpha.png", fields));
  EXPECT_EQ(trinary.at(0, 0), -1);
  EXPECT_EQ(trinary.at(1, 0), 100);  // (0 + 0 + 0 + 255) / 4: occupancy 0.75
}

TEST(OccupancyMap, TheOriginPlacesTheLowerLeftCornerWithItsYaw) {
  test::writePgm("yaw.pgm", {"..", "#."});  // the obstacle is cell (0, 0)
  WorldConfig config;
  config.map =
      test::writeMapYaml("yaw.yaml", "yaw.pgm",
                         "resolution: 0.5\norigin: [2.0, 1.0, 1.5707963267948966]\nnegate: 0\n"
                         "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  config.random_start = true;
  config.start_clearance = 0.0;
  config.region = {1.0, 1.0, 2.0, 2.0};  // the map's extent: the origin lies outside it
  const WorldModel world(config, 0.0);
  ASSERT_EQ(world.mapRectangles().size(), 1u);
  // Cell (0, 0)'s centre (0.25, 0.25) in the map frame, turned by 90 degrees about (2, 1).
  const Eigen::Vector2d centre = world.mapPose() * world.mapRectangles()[0].center();
  EXPECT_NEAR(centre.x(), 2.0 - 0.25, 1e-12);
  EXPECT_NEAR(centre.y(), 1.0 + 0.25, 1e-12);
  EXPECT_EQ(world.staticClearance({1.75, 1.25}), 0.0);  // on the obstacle cell
}

TEST(OccupancyMap, BadFilesAreRefusedNamingTheFieldAndValue) {
  test::writePgm("ok.pgm", {"..", ".."});
  const std::string good_fields =
      "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  std::string e = loadError(test::writeTempFile("no_res.yaml",
                                                "image: ok.pgm\norigin: [0, 0, 0]\nnegate: 0\n"
                                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  EXPECT_NE(e.find("missing field 'resolution'"), std::string::npos) << e;
  EXPECT_NE(e.find("no_res.yaml"), std::string::npos) << e;
  e = loadError(test::writeMapYaml("zero_res.yaml", "ok.pgm",
                                   "resolution: 0\norigin: [0, 0, 0]\nnegate: 0\n"
                                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  EXPECT_NE(e.find("resolution = 0"), std::string::npos) << e;
  e = loadError(test::writeMapYaml("order.yaml", "ok.pgm",
                                   "resolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                                   "occupied_thresh: 0.5\nfree_thresh: 0.7\n"));
  EXPECT_NE(e.find("free_thresh = 0.7"), std::string::npos) << e;
  e = loadError(test::writeMapYaml("origin.yaml", "ok.pgm",
                                   "resolution: 0.1\norigin: [0, 0]\nnegate: 0\n"
                                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  EXPECT_NE(e.find("origin = [0, 0]"), std::string::npos) << e;
  e = loadError(test::writeMapYaml("mode.yaml", "ok.pgm", good_fields + "mode: fuzzy\n"));
  EXPECT_NE(e.find("mode = 'fuzzy'"), std::string::npos) << e;
  e = loadError(test::writeMapYaml("missing_image.yaml", "no_such.pgm", good_fields));
  EXPECT_NE(e.find("image = '"), std::string::npos) << e;
  EXPECT_NE(e.find("no_such.pgm"), std::string::npos) << e;
  test::writeTempFile("not_an_image.pgm", "hello\n");
  e = loadError(test::writeMapYaml("bad_image.yaml", "not_an_image.pgm", good_fields));
  EXPECT_NE(e.find("cannot be read as an image"), std::string::npos) << e;
  e = loadError(::testing::TempDir() + "no_such_map.yaml");
  EXPECT_NE(e.find("cannot be read"), std::string::npos) << e;
  // A map image larger than 8192 px a side is refused from its header, before it is decoded (a
  // PGM whose header says 20000 x 20000 and holds one row).
  test::writeTempFile("huge.pgm", "P5\n20000 20000\n255\n" + std::string(20000, '\xfe'));
  e = loadError(test::writeMapYaml("huge.yaml", "huge.pgm", good_fields));
  EXPECT_NE(e.find("20000 x 20000 px: at most 8192 px a side"), std::string::npos) << e;
  EXPECT_NE(e.find("huge.pgm"), std::string::npos) << e;
}

}  // namespace
}  // namespace jetbot_rl
