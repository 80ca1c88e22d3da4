// Starts and goals in a map or a Gazebo world lie where the robot can drive from world/spawn
// (issue 48): never outside the building the grid reaches past, never inside a closed outline
// (a refrigerator's four walls); a world/region given is drawn in anywhere free as before; a
// spawn the footprint does not fit is refused naming world/spawn and what is there.
#include <gtest/gtest.h>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

std::string wallBox(const std::string& name, double x, double y, double sx, double sy) {
  const std::string pose = std::to_string(x) + " " + std::to_string(y) + " 0.5 0 0 0";
  return "<model name=\"" + name + "\"><static>true</static><pose>" + pose +
         "</pose><link name=\"link\"><collision name=\"c\"><geometry><box><size>" +
         std::to_string(sx) + " " + std::to_string(sy) +
         " 1</size></box></geometry></collision></link></model>\n";
}

/// Four walls of `thickness` around the square of side `side` centred on (x, y), named `name`.
std::string outline(const std::string& name, double x, double y, double side, double thickness) {
  const double h = 0.5 * (side + thickness), l = side + 2 * thickness;
  return wallBox(name + "_s", x, y - h, l, thickness) +
         wallBox(name + "_n", x, y + h, l, thickness) +
         wallBox(name + "_w", x - h, y, thickness, l) +
         wallBox(name + "_e", x + h, y, thickness, l);
}

/// A house of 6 x 6 m inside (its grid reaches 1 m past the walls) with a refrigerator of
/// 1.4 x 1.4 m (its cross-section: four thin walls, hollow) at (1.5, 1.5).
std::string houseWorld() {
  return test::sdfWorld(
      "house.world", outline("house", 0.0, 0.0, 6.0, 0.1) + outline("fridge", 1.5, 1.5, 1.4, 0.04));
}

bool inHouse(const Eigen::Vector2d& p) { return p.cwiseAbs().maxCoeff() < 3.0; }
bool inFridge(const Eigen::Vector2d& p) {
  return (p - Eigen::Vector2d(1.5, 1.5)).cwiseAbs().maxCoeff() < 0.74;
}

EnvConfig houseConfig() {
  EnvConfig c = test::smallConfig(16, 2);
  c.world.gazebo_world = houseWorld();
  c.world.random_start = true;
  c.world.spawn = {-1.5, -1.5};
  c.world.start_clearance = 0.2;
  c.scan.link = "base_link";
  c.scan.samples = 24;
  c.scan.range = {0.05, 3.5};
  c.episode_length_s = 0.05;  // a reset every step
  return c;
}

/// Starts and goals of 16 envs over 60 resets each: how many lay outside the house, how many
/// inside the refrigerator.
struct Draws {
  int outside = 0, in_fridge = 0, total = 0;
};
Draws drawMany(const EnvConfig& c) {
  BatchedEnv env(test::jetbot(), c, test::navigationTask());
  const auto& task = dynamic_cast<const NavigationTask&>(env.task());
  Draws d;
  for (int s = 0; s < 60; ++s) {
    env.step(std::vector<float>(32, 0.0f));
    for (int e = 0; e < 16; ++e) {
      for (const Eigen::Vector2d& p : {env.view(e).layout().start, task.goal(e)}) {
        d.outside += !inHouse(p);
        d.in_fridge += inFridge(p);
        ++d.total;
      }
    }
  }
  return d;
}

TEST(SpawnReach, StartsAndGoalsOfAGazeboWorldStayWhereTheRobotCanDriveFromItsSpawn) {
  const Draws d = drawMany(houseConfig());
  EXPECT_EQ(d.total, 16 * 60 * 2);
  EXPECT_EQ(d.outside, 0);
  EXPECT_EQ(d.in_fridge, 0);
}

TEST(SpawnReach, AGivenRegionIsDrawnInAnywhereFreeAsBefore) {
  // The same world with its whole grid as the region: starts and goals outside the walls and
  // inside the refrigerator (what issue 48 measured), so the check above can fail.
  EnvConfig c = houseConfig();
  c.world.region = {-4.2, -4.2, 4.2, 4.2};
  const Draws d = drawMany(c);
  EXPECT_GT(d.outside, d.total / 20);
  EXPECT_GT(d.in_fridge, 0);
}

TEST(SpawnReach, TheReachFollowsTheFootprintThroughADoorAndStopsAtAGapTooNarrow) {
  // Two rooms joined by a door: 0.5 m wide, the robot passes; 0.1 m, it does not.
  for (const double door : {0.5, 0.1}) {
    const double w = 0.5 * (6.0 - door), y = 0.5 * (door + w);  // the dividing wall's halves
    const std::string world = test::sdfWorld("rooms.world", outline("house", 0.0, 0.0, 6.0, 0.1) +
                                                                wallBox("south", 0.0, -y, 0.1, w) +
                                                                wallBox("north", 0.0, y, 0.1, w));
    WorldConfig c;
    c.gazebo_world = world;
    c.random_start = true;
    c.spawn = {-1.5, 0.0};
    const WorldModel model(c, 0.1);
    ASSERT_NE(model.spawnReach(), nullptr);
    EXPECT_TRUE(model.inReach({-2.0, 2.0}));
    EXPECT_EQ(model.inReach({2.0, 2.0}), door > 0.3) << "door " << door;
    EXPECT_FALSE(model.inReach({3.5, 0.0}));  // outside the house
  }
}

TEST(SpawnReach, ASpawnTheFootprintDoesNotFitIsRefusedNamingItAndWhatIsThere) {
  EnvConfig c = houseConfig();
  c.world.spawn = {3.0, 0.0};  // in the house's east wall
  try {
    BatchedEnv env(test::jetbot(), c, test::navigationTask());
    ADD_FAILURE() << "accepted a spawn inside a wall";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("world/spawn"), std::string::npos) << m;
    EXPECT_NE(m.find("[3, 0]"), std::string::npos) << m;
    EXPECT_NE(m.find("house_e"), std::string::npos) << m;
    EXPECT_NE(m.find("world/region"), std::string::npos) << m;
  }
}

TEST(SpawnReach, AMapsUnknownCellsAroundTheSpawnAreRefused) {
  // A map_server map: free inside, unknown around; the spawn in the unknown border.
  std::vector<std::string> rows(20, std::string(20, '.'));
  for (int i = 0; i < 20; ++i) rows[0][i] = rows[19][i] = rows[i][0] = rows[i][19] = '?';
  test::writePgm("reach.pgm", rows);
  WorldConfig c;
  c.map = test::writeMapYaml("reach.yaml", "reach.pgm");
  c.random_start = true;
  c.spawn = {0.05, 1.0};
  try {
    WorldModel model(c, 0.1);
    ADD_FAILURE() << "accepted a spawn in the map's unknown cells";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("world/spawn"), std::string::npos) << e.what();
  }
  c.spawn = {1.0, 1.0};
  const WorldModel model(c, 0.1);
  EXPECT_TRUE(model.inReach({0.5, 1.5}));
  EXPECT_FALSE(model.inReach({0.05, 1.5}));
}

}  // namespace
}  // namespace jetbot_rl
