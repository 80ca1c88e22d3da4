// A robot's global planner on its map (the deploy node's paths, issue 30 part 4): goals refused
// with their reason, a path through a door, no path through a closed one, scan points the map
// does not hold closing the way while those on its walls change nothing, a start brushing a
// wall, and a map with no room for the robot.
#include <gtest/gtest.h>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/map_planner.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

constexpr double kRes = 0.1;

/// Two 2 x 2 m rooms side by side (x in [0, 4], y in [0, 2], cells of 0.1 m), walls around
/// them and between them at x in [2.0, 2.1) with a door of `door_cells` cells at y from 0.8 m;
/// the top-right corner cell is unknown.
OccupancyMap twoRooms(int door_cells) {
  OccupancyMap map;
  map.resolution = kRes;
  map.width = 41;
  map.height = 21;
  map.data.assign(static_cast<std::size_t>(map.width) * map.height, 0);
  const auto set = [&map](int x, int y, std::int8_t v) {
    map.data[static_cast<std::size_t>(y) * map.width + x] = v;
  };
  for (int x = 0; x < map.width; ++x) {
    set(x, 0, 100);
    set(x, map.height - 1, 100);
  }
  for (int y = 0; y < map.height; ++y) {
    set(0, y, 100);
    set(map.width - 1, y, 100);
    if (y < 8 || y >= 8 + door_cells) set(20, y, 100);
  }
  set(map.width - 2, map.height - 2, -1);
  return map;
}

MapPlannerConfig config() {
  MapPlannerConfig c;
  c.robot_radius = 0.15;
  c.clearance = 0.1;
  return c;
}

TEST(MapPlanner, PlansThroughTheDoorIntoTheOtherRoom) {
  const MapPlanner planner(twoRooms(6), config());
  const Eigen::Vector2d start(0.6, 0.5), goal(3.4, 1.5);
  std::vector<Eigen::Vector2d> path;
  ASSERT_EQ(planner.plan(start, goal, {}, path), "");
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path.front(), start);
  EXPECT_EQ(path.back(), goal);
  // It crosses the wall's line within the door (y in [0.8, 1.4]), keeping the footprint.
  bool crossed = false;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    if ((a.x() - 2.05) * (b.x() - 2.05) > 0.0) continue;
    const double y = a.y() + (b.y() - a.y()) * (2.05 - a.x()) / (b.x() - a.x());
    EXPECT_GT(y, 0.8 + 0.15);
    EXPECT_LT(y, 1.4 - 0.15);
    crossed = true;
  }
  EXPECT_TRUE(crossed);
  EXPECT_GT(test::pathLength(path), (goal - start).norm());
  // Deterministic.
  std::vector<Eigen::Vector2d> again;
  ASSERT_EQ(planner.plan(start, goal, {}, again), "");
  EXPECT_EQ(again, path);
}

TEST(MapPlanner, RefusesGoalsNamingWhy) {
  const MapPlanner planner(twoRooms(6), config());
  std::vector<Eigen::Vector2d> path;
  const Eigen::Vector2d start(0.6, 0.5);
  EXPECT_NE(planner.plan(start, {9.0, 1.0}, {}, path).find("outside the map"), std::string::npos);
  EXPECT_TRUE(path.empty());
  EXPECT_NE(planner.checkGoal({2.05, 0.3}).find("in an obstacle"), std::string::npos);
  EXPECT_NE(planner.checkGoal({3.95, 1.95}).find("unknown cell"), std::string::npos);
  EXPECT_NE(planner.checkGoal({0.15, 1.0}).find("within the robot's footprint"), std::string::npos);
  EXPECT_EQ(planner.checkGoal({std::nan(""), 1.0}), "not finite");
  EXPECT_EQ(planner.checkGoal({3.0, 1.0}), "");
}

TEST(MapPlanner, NoPathThroughADoorTooNarrowForTheFootprint) {
  // Two cells (0.2 m) for a robot of 0.3 m.
  const MapPlanner planner(twoRooms(2), config());
  std::vector<Eigen::Vector2d> path;
  const std::string why = planner.plan({0.6, 0.5}, {3.4, 1.5}, {}, path);
  EXPECT_NE(why.find("no path for the robot's footprint"), std::string::npos) << why;
  EXPECT_TRUE(path.empty());
}

TEST(MapPlanner, WhatTheScanSeesClosesTheWayAndTheMapsWallsChangeNothing) {
  const MapPlanner planner(twoRooms(6), config());
  const Eigen::Vector2d start(0.6, 0.5), goal(3.4, 1.5);
  std::vector<Eigen::Vector2d> plain, path;
  ASSERT_EQ(planner.plan(start, goal, {}, plain), "");
  // Endpoints on the walls (a scan of the room) are explained by the map.
  std::vector<Eigen::Vector2d> walls;
  for (double y = 0.1; y < 0.8; y += 0.02) walls.push_back({1.995, y});
  for (double x = 0.1; x < 2.0; x += 0.02) walls.push_back({x, 0.1});
  for (const auto& p : walls) EXPECT_TRUE(planner.explainedByMap(p)) << p.transpose();
  ASSERT_EQ(planner.plan(start, goal, walls, path), "");
  EXPECT_EQ(path, plain);
  // A row of points across the door (a closed door the map does not know).
  std::vector<Eigen::Vector2d> door;
  for (double y = 0.8; y <= 1.4; y += 0.02) door.push_back({2.05, y});
  EXPECT_FALSE(planner.explainedByMap({2.05, 1.1}));
  const std::string why = planner.plan(start, goal, door, path);
  EXPECT_NE(why.find("no path"), std::string::npos) << why;
  // A post in the room is gone round.
  ASSERT_EQ(planner.plan({0.5, 1.0}, {1.5, 1.0}, {{1.0, 1.0}}, path), "");
  EXPECT_GE(path.size(), 3u);
  EXPECT_GT(test::pathLength(path), 1.0);
}

TEST(MapPlanner, AStartBrushingAWallLeavesFromTheNearestFreeCell) {
  const MapPlanner planner(twoRooms(6), config());
  const Eigen::Vector2d start(0.22, 1.0);  // 0.12 m from the wall: within the footprint
  std::vector<Eigen::Vector2d> path;
  ASSERT_EQ(planner.plan(start, {1.5, 1.0}, {}, path), "");
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path.front(), start);
  EXPECT_LT((path[1] - start).norm(), 0.15 + 1e-9);
  EXPECT_GT(path[1].x(), start.x());
  // Pushed into a wall's end (the footprint half in it) it finds one too.
  ASSERT_EQ(planner.plan({2.02, 0.87}, {1.5, 1.0}, {}, path), "");
  EXPECT_EQ(path.front(), Eigen::Vector2d(2.02, 0.87));
  // Off the map there is none.
  const std::string why = planner.plan({-1.0, -1.0}, {1.5, 1.0}, {}, path);
  EXPECT_NE(why.find("no free cell"), std::string::npos) << why;
}

TEST(MapPlanner, AMapWithoutRoomForTheRobotIsRefused) {
  OccupancyMap map = twoRooms(6);
  std::fill(map.data.begin(), map.data.end(), 100);
  EXPECT_THROW(MapPlanner(map, config()), ConfigError);
}

}  // namespace
}  // namespace jetbot_rl
