// Gazebo worlds (world/gazebo_world): collision poses through nested models, links, collisions and
// frames against hand-computed ones; upright shapes exact (a scan of the world equals the scan of
// the same boxes and cylinders given as obstacles, bit for bit); the cut grid against a hand-made
// one; repeated models folded to the same solids; the map file round trip; bad files refused
// naming the file, line, mesh or model; determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "gazebo_test_util.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/robot/package_path.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

using test::sdfWorld;

std::string shippedWorld() {
  return std::string(JETBOT_RL_SOURCE_DIR) + "/worlds/furnished_room.world";
}

using test::box;
using test::cylinder;
using test::GazeboWorldTest;
using test::solid;
using test::staticModel;

TEST_F(GazeboWorldTest, PosesComposeThroughNestedModelsLinksCollisionsAndFrames) {
  const GazeboWorld world = loadGazeboWorld(shippedWorld());
  EXPECT_EQ(world.name, "furnished_room");
  EXPECT_EQ(world.models,
            9);  // ground, walls, 2 tables, counter, lounge and its sofa, ball, barrel
  // lounge at (1.2, -0.9) turned 30 degrees; its nested sofa's back at (0, -0.3) in the sofa.
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  const WorldSolid& back = solid(world, "lounge::sofa::body::back");
  ASSERT_TRUE(back.upright);
  EXPECT_NEAR(back.upright->center.x(), 1.2 + 0.3 * s, 1e-12);
  EXPECT_NEAR(back.upright->center.y(), -0.9 - 0.3 * c, 1e-12);
  EXPECT_NEAR(back.upright->yaw, kPi / 6, 1e-12);
  EXPECT_NEAR(back.upright->half_extents.x(), 0.7, 1e-12);
  EXPECT_NEAR(back.top, 0.9, 1e-12);
  // The side table's link is posed relative to the lounge's frame "corner" (0.9, 0.45), + 0.2.
  const WorldSolid& side = solid(world, "lounge::side_table::top");
  ASSERT_TRUE(side.upright);
  EXPECT_NEAR(side.upright->center.x(), 1.2 + 1.1 * c - 0.45 * s, 1e-12);
  EXPECT_NEAR(side.upright->center.y(), -0.9 + 1.1 * s + 0.45 * c, 1e-12);
  // An included model turned 0.3 rad: a leg at (0.55, 0.35) of table_1 at (-1.5, 1.2).
  const WorldSolid& leg = solid(world, "table_1::body::leg_1");
  ASSERT_TRUE(leg.upright);
  EXPECT_NEAR(leg.upright->center.x(), -1.5 + 0.55 * std::cos(0.3) - 0.35 * std::sin(0.3), 1e-12);
  EXPECT_NEAR(leg.upright->center.y(), 1.2 + 0.55 * std::sin(0.3) + 0.35 * std::cos(0.3), 1e-12);
  EXPECT_NEAR(leg.upright->radius, 0.03, 1e-12);
  // A wall turned a quarter turn is an upright box whose sides follow the turn.
  const WorldSolid& east = solid(world, "walls::link::east");
  ASSERT_TRUE(east.upright);
  EXPECT_NEAR(east.bounds.min().x(), 3.0, 1e-9);
  EXPECT_NEAR(east.bounds.max().y(), 2.5, 1e-9);
  // What is not read is named.
  EXPECT_NE(world.skipped.find("plane 'ground_plane::link::collision'"), std::string::npos);
  EXPECT_NE(world.skipped.find("1 lights"), std::string::npos);
  EXPECT_NE(world.skipped.find("1 <plugin>"), std::string::npos);
  EXPECT_NE(world.skipped.find("1 <physics>"), std::string::npos);
}

TEST_F(GazeboWorldTest, ACylinderOnItsSideAndAScaledMeshKeepTheirShapes) {
  const GazeboWorld world = loadGazeboWorld(shippedWorld());
  // The barrel: radius 0.25, length 0.9 along the world's y (rolled a quarter turn) at
  // (-1.1, -0.3, 0.25): its surface, not an upright cylinder.
  const WorldSolid& barrel = solid(world, "barrel::link::collision");
  EXPECT_FALSE(barrel.upright);
  const double grow = 1.0 / std::cos(kPi / 32);  // its facets lie outside the round surface
  EXPECT_NEAR(barrel.bounds.min().y(), -0.75, 1e-9);
  EXPECT_NEAR(barrel.bounds.max().y(), 0.15, 1e-9);
  EXPECT_LE(barrel.bounds.min().x(), -1.35);
  EXPECT_GE(barrel.bounds.min().x(), -1.1 - 0.25 * grow - 1e-9);
  EXPECT_NEAR(barrel.bottom, 0.25 - 0.25 * grow, 1e-9);
  // The counter: an L drawn in millimetres, scaled by 0.001, at (-2.95, -2.45).
  const WorldSolid& counter = solid(world, "counter::body::collision");
  EXPECT_FALSE(counter.upright);
  EXPECT_EQ(counter.triangles.size(), 20u * 3);
  EXPECT_NEAR(counter.bounds.min().x(), -2.95, 1e-9);
  EXPECT_NEAR(counter.bounds.min().y(), -2.45, 1e-9);
  EXPECT_NEAR(counter.bounds.max().x(), -1.75, 1e-9);
  EXPECT_NEAR(counter.bounds.max().y(), -1.45, 1e-9);
  EXPECT_NEAR(counter.top, 0.9, 1e-9);
  // Its cut is the L, not its hull: the notch is free, the arms are not.
  WorldConfig config;
  config.gazebo_world = shippedWorld();
  config.cut_height = 0.1;
  const WorldModel model(config, 0.1);
  EXPECT_GT(model.staticClearance({-2.0, -1.6}), 0.0);  // in the notch
  EXPECT_EQ(model.staticClearance({-2.0, -2.2}), 0.0);  // in the long arm
  EXPECT_EQ(model.staticClearance({-2.8, -1.6}), 0.0);  // in the short arm
  // The table tops (0.72 to 0.75 m) are above the cut; their legs are in it.
  EXPECT_GT(model.staticClearance({-1.5, 1.2}), 0.2);
  EXPECT_EQ(model.worldObstacles().size(), 4u + 8u + 3u);  // walls, legs, sofa (2), side table
}

TEST_F(GazeboWorldTest, TheCutGridIsTheCellsTheCrossSectionsTouch) {
  // A box 0.35 x 0.15 at (0.2, 0.1), a cylinder of radius 0.12 at (-0.25, -0.25), a box above the
  // cut, all cut at 0.3 m into cells of 0.1 m from (-0.5, -0.5).
  const std::string path = sdfWorld(
      "cut.world",
      staticModel("a", "0.2 0.1 0.5 0 0 0", box("b", "0 0 0 0 0 0", "0.35 0.15 1")) +
          staticModel("c", "-0.25 -0.25 0 0 0 0", cylinder("c", "0 0 0.5 0 0 0", 0.12, 1.0)) +
          staticModel("high", "0.3 -0.3 2 0 0 0", box("b", "0 0 0 0 0 0", "0.3 0.3 0.2")));
  const GazeboWorld world = loadGazeboWorld(path);
  const Eigen::AlignedBox2d area(Eigen::Vector2d(-0.5, -0.5), Eigen::Vector2d(1.0, 1.0));
  const OccupancyMap map = cutSolids(world.solids, 0.3, 0.1, area);
  ASSERT_EQ(map.width, 15);
  ASSERT_EQ(map.height, 15);
  // By hand: the box spans x in [0.025, 0.375] (columns 5 to 8), y in [0.025, 0.175] (rows 5, 6);
  // the cylinder's centre is cell (2.5, 2.5) with radius 1.2 cells: columns and rows 1 to 3.
  std::vector<std::int8_t> expected(15 * 15, 0);
  for (int y = 5; y <= 6; ++y) {
    for (int x = 5; x <= 8; ++x) expected[y * 15 + x] = 100;
  }
  for (int y = 1; y <= 3; ++y) {
    for (int x = 1; x <= 3; ++x) expected[y * 15 + x] = 100;
  }
  EXPECT_EQ(map.data, expected);
  // The cut area: the crossing solids' extent and a margin, on the cells' lattice.
  const Eigen::AlignedBox2d fitted = cutArea(world.solids, 0.3, 0.1, 0.2);
  EXPECT_NEAR(fitted.min().x(), -0.6, 1e-12);
  EXPECT_NEAR(fitted.max().x(), 0.6, 1e-12);
  EXPECT_NEAR(fitted.max().y(), 0.4, 1e-12);
}

TEST_F(GazeboWorldTest, AScanOfTheWorldEqualsTheScanOfItsShapesGivenAsObstacles) {
  // Boxes and cylinders in a model turned 0.7 rad holding a nested model turned again.
  const std::string path =
      sdfWorld("scan.world",
               "<model name=\"outer\"><static>true</static><pose>1 0.5 0 0 0 0.7</pose>"
               "<link name=\"l\">" +
                   box("b", "0.8 0 0.25 0 0 0.2", "0.4 0.3 0.5") +
                   cylinder("c", "0 1.2 0.4 0 0 0", 0.15, 0.8) +
                   "</link><model name=\"inner\"><pose>-1.5 0 0 0 0 -1.2</pose><link name=\"l\">" +
                   box("b", "0.5 0.5 0.3 0 0 0", "1.0 0.1 0.6") + "</link></model></model>\n");
  WorldConfig config;
  config.gazebo_world = path;
  config.cut_height = 0.1;
  config.random_start = true;  // the origin is inside the inner box: starts over the region
  config.region = {-3.0, -3.0, 3.0, 3.0};
  const WorldModel world(config, 0.1);
  // The same shapes by hand, as obstacles.
  const auto place = [](double yaw, const Eigen::Vector2d& at, const Eigen::Vector2d& p) {
    return Eigen::Vector2d(at + Eigen::Rotation2Dd(yaw) * p);
  };
  std::vector<Obstacle> by_hand(3);
  by_hand[0].center = place(0.7, {1.0, 0.5}, {0.8, 0.0});
  by_hand[0].yaw = 0.9;
  by_hand[0].half_extents = {0.2, 0.15};
  by_hand[0].height = 0.5;
  by_hand[1].shape = Obstacle::Shape::kCylinder;
  by_hand[1].center = place(0.7, {1.0, 0.5}, {0.0, 1.2});
  by_hand[1].radius = 0.15;
  by_hand[1].height = 0.8;
  by_hand[2].center = place(0.7, {1.0, 0.5}, place(-1.2, {-1.5, 0.0}, {0.5, 0.5}));
  by_hand[2].yaw = -0.5;
  by_hand[2].half_extents = {0.5, 0.05};
  by_hand[2].height = 0.6;
  ASSERT_EQ(world.worldObstacles().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Obstacle& o = world.worldObstacles()[i];
    EXPECT_NEAR((o.center - by_hand[i].center).norm(), 0.0, 1e-12) << i;
    if (o.shape == Obstacle::Shape::kBox) {
      EXPECT_NEAR(std::remainder(o.yaw - by_hand[i].yaw, 2 * kPi), 0.0, 1e-12) << i;
    }
    by_hand[i] = o;  // bit for bit below: the same doubles
  }
  const ScannerSpec spec = test::fullTurnScanner(0.05, 8.0);
  int hits = 0;
  for (const Eigen::Vector2d& at :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.5, -0.5), Eigen::Vector2d(-2.0, 2.0)}) {
    Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
    sensor.translation() = Eigen::Vector3d(at.x(), at.y(), 0.1);
    std::vector<float> from_world(360), from_obstacles(360);
    Rng a(1), b(1);
    castScan(spec, &world, {}, sensor, a, from_world.data());
    castScan(spec, nullptr, by_hand, sensor, b, from_obstacles.data());
    EXPECT_EQ(std::memcmp(from_world.data(), from_obstacles.data(), 360 * sizeof(float)), 0);
    for (float r : from_world) hits += std::isfinite(r) ? 1 : 0;
  }
  EXPECT_GT(hits, 100);
}

TEST_F(GazeboWorldTest, TheShippedWorldScansAsItsBoxesAndCylindersOverAMapOfTheRest) {
  // The same layout drawn without Gazebo: its upright shapes as obstacles, the cells of its
  // other shapes as a map_server map (written and read back), placed where the grid lies.
  WorldConfig config;
  config.gazebo_world = shippedWorld();
  const WorldModel room(config, 0.1);
  OccupancyMap others = *room.map();
  for (std::size_t i = 0; i < others.data.size(); ++i) {
    others.data[i] = room.obstacleCells()[i] ? 100 : 0;
  }
  const std::string path = ::testing::TempDir() + "room_others.yaml";
  writeMapYaml(others, path);
  WorldConfig drawn;
  drawn.map = path;
  const WorldModel map_world(drawn, 0.1);
  const ScannerSpec spec = test::fullTurnScanner(0.05, 8.0);
  int hits = 0;
  for (const Eigen::Vector2d& at :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(-1.5, -1.9), Eigen::Vector2d(2.0, 0.8)}) {
    Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
    sensor.translation() = Eigen::Vector3d(at.x(), at.y(), room.cutHeight());
    std::vector<float> in_room(360), as_drawn(360);
    Rng a(1), b(1);
    castScan(spec, &room, {}, sensor, a, in_room.data());
    castScan(spec, &map_world, room.worldObstacles(), sensor, b, as_drawn.data());
    EXPECT_EQ(std::memcmp(in_room.data(), as_drawn.data(), 360 * sizeof(float)), 0) << at;
    for (float r : in_room) hits += std::isfinite(r) ? 1 : 0;
  }
  EXPECT_EQ(hits, 3 * 360);  // a closed room
}

TEST_F(GazeboWorldTest, RepeatedModelsGiveTheSolidsEachWouldGive) {
  // Posts alike but for name and pose (folded: parsed once), one turned upside down and one
  // rolled (then its surface), one placed relative to another; the same posts each made unique
  // by a no-op <static> difference (not folded) give the same solids.
  const auto post = [](const std::string& name, const std::string& pose, const std::string& extra) {
    return "<model name=\"" + name + "\">" + extra + "<pose" + pose + "</pose><link name=\"l\">" +
           "<collision name=\"c\"><pose>0.1 0 0.5 0 0 0</pose><geometry><cylinder><radius>0.1"
           "</radius><length>1</length></cylinder></geometry></collision>"
           "<collision name=\"b\"><pose>0 0 0.2 0 0 0.3</pose><geometry><box><size>0.3 0.2 0.4"
           "</size></box></geometry></collision></link></model>\n";
  };
  const std::vector<std::pair<std::string, std::string>> posts{
      {"p0", ">0 0 0 0 0 0"},
      {"p1", ">2 1 0 0 0 1.1"},
      {"p2", ">-1 2 1 3.14159265358979 0 0"},
      {"p3", ">1 -2 0.3 0.4 0 0"},
      {"p4", " relative_to=\"p1\">1 0 0 0 0 0.5"}};
  std::string folded, unique;
  for (std::size_t i = 0; i < posts.size(); ++i) {
    folded += post(posts[i].first, posts[i].second, "");
    unique += post(posts[i].first, posts[i].second,
                   i % 2 ? "<static>true</static>" : "<static>false</static>");
  }
  const GazeboWorld a = loadGazeboWorld(sdfWorld("folded.world", folded));
  const GazeboWorld b = loadGazeboWorld(sdfWorld("unique.world", unique));
  ASSERT_EQ(a.solids.size(), 10u);
  ASSERT_EQ(b.solids.size(), 10u);
  EXPECT_EQ(a.models, 5);
  int surfaces = 0;
  for (const WorldSolid& s : b.solids) {
    const WorldSolid& f = solid(a, s.name);
    ASSERT_EQ(bool(f.upright), bool(s.upright)) << s.name;
    // A rolled cylinder's facets may start at another angle: within a facet's depth.
    const double within = s.upright ? 1e-9 : 1e-3;
    EXPECT_NEAR(f.bottom, s.bottom, within) << s.name;
    EXPECT_NEAR(f.top, s.top, within) << s.name;
    EXPECT_NEAR((f.bounds.min() - s.bounds.min()).norm(), 0.0, within) << s.name;
    EXPECT_NEAR((f.bounds.max() - s.bounds.max()).norm(), 0.0, within) << s.name;
    if (s.upright) {
      EXPECT_NEAR((f.upright->center - s.upright->center).norm(), 0.0, 1e-9) << s.name;
      if (s.upright->shape == Obstacle::Shape::kBox) {
        EXPECT_NEAR(std::remainder(f.upright->yaw - s.upright->yaw, kPi), 0.0, 1e-9) << s.name;
      }
    } else {
      ++surfaces;
    }
  }
  EXPECT_EQ(surfaces, 2);  // p3's two shapes, rolled 0.4 rad
}

TEST_F(GazeboWorldTest, IncludesRelativeToTheWorldFileAreFound) {
  // A model folder named by a path relative to the world file, included once and three times
  // (then read once, the repeats as frames: their URIs must still resolve from the file).
  const std::string table = std::filesystem::relative(
      std::string(JETBOT_RL_SOURCE_DIR) + "/models/jetbot_rl_table", ::testing::TempDir());
  const auto include = [&](const std::string& name, const std::string& pose) {
    return "<include><uri>" + table + "</uri><name>" + name + "</name><pose>" + pose +
           "</pose></include>\n";
  };
  const GazeboWorld one = loadGazeboWorld(sdfWorld("one.world", include("t0", "1 2 0 0 0 0")));
  EXPECT_EQ(one.solids.size(), 5u);
  const GazeboWorld three = loadGazeboWorld(
      sdfWorld("three.world", include("t0", "1 2 0 0 0 0") + include("t1", "-1 0 0 0 0 0") +
                                  include("t2", "0 -2 0 0 0 1.57")));
  ASSERT_EQ(three.solids.size(), 15u);
  const WorldSolid& leg = solid(three, "t1::body::leg_1");
  ASSERT_TRUE(leg.upright);
  EXPECT_NEAR((leg.upright->center - Eigen::Vector2d(-1.0 + 0.55, 0.35)).norm(), 0.0, 1e-12);
}

TEST_F(GazeboWorldTest, TheGridWrittenAsAMapReadsBackAsTheSameCells) {
  WorldConfig config;
  config.gazebo_world = shippedWorld();
  const WorldModel world(config, 0.1);
  const std::string path = ::testing::TempDir() + "room_map.yaml";
  writeMapYaml(*world.map(), path);
  const OccupancyMap read = OccupancyMap::fromYamlFile(path);
  EXPECT_EQ(read.width, world.map()->width);
  EXPECT_EQ(read.height, world.map()->height);
  EXPECT_NEAR(read.origin_x, world.map()->origin_x, 1e-12);
  EXPECT_NEAR(read.origin_y, world.map()->origin_y, 1e-12);
  EXPECT_EQ(read.resolution, world.map()->resolution);
  EXPECT_EQ(read.data, world.map()->data);
  int occupied = 0;
  for (std::int8_t v : read.data) occupied += v == 100;
  EXPECT_GT(occupied, 1000);
}

void expectRefused(const WorldConfig& config, const std::vector<std::string>& words) {
  try {
    validateConfig(config);  // as the env does, once, before it builds its world
    WorldModel world(config, 0.1);
    FAIL() << "accepted " << config.gazebo_world;
  } catch (const ConfigError& e) {
    for (const std::string& w : words) {
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what() << " lacks " << w;
    }
  }
}

TEST_F(GazeboWorldTest, BadFilesAreRefusedNamingTheFileLineMeshOrModel) {
  WorldConfig config;
  config.gazebo_world = test::writeTempFile("not_sdf.world", "just some text\n");
  expectRefused(config, {"world/gazebo_world", "not_sdf.world:1: not XML"});
  config.gazebo_world = test::writeTempFile("robot.urdf", "<robot name=\"r\"/>\n");
  expectRefused(config, {"world/gazebo_world", "robot.urdf", "<robot>, not <sdf>"});
  config.gazebo_world =
      test::writeTempFile("unclosed.world",
                          "<sdf version=\"1.6\">\n<world name=\"w\">\n<model name=\"a\">\n"
                          "</world>\n</sdf>\n");
  // tinyxml2 names the line of the element left open.
  expectRefused(config, {"world/gazebo_world", "unclosed.world:3: not XML", "name=model"});
  config.gazebo_world = sdfWorld("version.world", staticModel("a", "0 0 0 0 0 0", ""), "9.9");
  expectRefused(config, {"world/gazebo_world", "version.world:2", "9.9", "1.9"});
  config.gazebo_world =
      sdfWorld("size.world", staticModel("a", "0 0 0 0 0 0", box("b", "0 0 0 0 0 0", "1 1")));
  expectRefused(config, {"world/gazebo_world", "size.world:4", "<size>"});
  config.gazebo_world = sdfWorld("broken.world",
                                 "<model name=\"a\">\n<link name=\"l\">\n"
                                 "<collision name=\"c\"><pose relative_to=\"x\">"
                                 "0 0 0 0 0 0</pose><geometry><box><size>1 1 1"
                                 "</size></box></geometry></collision>\n"
                                 "</link></model>\n");
  expectRefused(config, {"world/gazebo_world", "broken.world", "a::l::c", "[x]"});
  config.gazebo_world = sdfWorld(
      "include.world", "<include><uri>model://no_such_model</uri><name>x</name></include>\n");
  expectRefused(config, {"world/gazebo_world", "model://no_such_model"});
  const std::string not_mesh = test::writeTempFile("not_a_mesh.stl", "nothing here\n");
  config.gazebo_world =
      sdfWorld("mesh.world",
               "<model name=\"m\"><static>true</static><link name=\"l\"><collision "
               "name=\"c\"><geometry><mesh><uri>" +
                   not_mesh + "</uri></mesh></geometry></collision></link></model>\n");
  expectRefused(config, {"world/gazebo_world", "m::l::c", "not_a_mesh.stl"});
  // The spawn inside a table leg of the shipped world: refused naming the leg.
  config.gazebo_world = shippedWorld();
  config.spawn = {-1.078, 1.6969};
  expectRefused(config, {"world/spawn", "table_1::body::leg_1", "furnished_room.world"});
  config.spawn = {0.0, 0.0};
  config.cut_height = 5.0;  // above everything
  expectRefused(config, {"world/gazebo_world", "world/cut_height"});
  config.cut_height = 0.0;
  config.map = "maps/office.yaml";
  expectRefused(config, {"world/gazebo_world", "world/map"});
}

TEST_F(GazeboWorldTest, TheSameSeedGivesTheSameEpisodesOnAnyThreadCount) {
  std::vector<std::vector<float>> runs;
  for (int threads : {1, 2}) {
    EnvConfig c;
    c.num_envs = 8;
    c.num_threads = threads;
    c.world.gazebo_world = shippedWorld();
    c.world.random_start = true;
    c.scan.link = "base_link";
    c.scan.samples = 90;
    c.episode_length_s = 0.5;
    c.randomization.initial_yaw = {-3.14, 3.14};
    BatchedEnv env(test::jetbot(), c);
    EXPECT_NEAR(env.world()->cutHeight(), scannerHeight(env.robot(), *env.scanner()), 1e-12);
    std::vector<float> trace;
    Rng rng(5);
    std::vector<float> actions(16);
    for (int s = 0; s < 120; ++s) {
      for (float& a : actions) a = static_cast<float>(40.0 * rng.uniform() - 20.0);
      const StepResult& r = env.step(actions);
      trace.insert(trace.end(), r.observations.begin(), r.observations.end());
      for (int e = 0; e < 8; ++e) {
        const float* scan = env.view(e).scan();
        trace.insert(trace.end(), scan, scan + 90);
      }
    }
    runs.push_back(trace);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_EQ(std::memcmp(runs[0].data(), runs[1].data(), runs[0].size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace jetbot_rl
