#include "jetbot_rl/planning/map_planner.h"

#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"

namespace jetbot_rl {
namespace {

std::string pointText(const Eigen::Vector2d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

/// The free cell of `grid` nearest `p` within `radius` [m], or -1.
long nearestFreeCell(const FootprintGrid& grid, const Eigen::Vector2d& p, double radius) {
  const int reach = static_cast<int>(std::ceil(radius / grid.resolution()));
  long best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  const double step = grid.resolution();
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const long c = grid.cellOf(p + step * Eigen::Vector2d(dx, dy));
      if (!grid.isFreeCell(c)) continue;
      const double d = (grid.centre(c) - p).norm();
      if (d <= radius && (d < best_distance || (d == best_distance && c < best))) {
        best = c;
        best_distance = d;
      }
    }
  }
  return best;
}

}  // namespace

MapPlanner::MapPlanner(const OccupancyMap& map, const MapPlannerConfig& config) : config_(config) {
  WorldConfig world;
  world.random_start = true;  // the map's origin need not be free: only somewhere
  world.start_clearance = 0.0;
  // Anywhere on the map, not only where the robot can drive from the origin (spawnReach()).
  const Eigen::AlignedBox2d extent = map.extent();
  world.region = {extent.min().x(), extent.min().y(), extent.max().x(), extent.max().y()};
  try {
    world_ = std::make_shared<const WorldModel>(world, config.robot_radius, map);
  } catch (const ConfigError& e) {
    throw ConfigError("the map has no free cell for the robot's footprint (" +
                      std::to_string(config.robot_radius) + " m): " + e.what());
  }
}

std::string MapPlanner::checkGoal(const Eigen::Vector2d& goal) const {
  const OccupancyMap& map = *world_->map();
  int x = 0, y = 0;
  if (!goal.allFinite()) return "not finite";
  if (!map.cellOf(goal, x, y)) return "outside the map";
  if (!map.isFree(x, y)) {
    return map.at(x, y) == -1 ? "on an unknown cell of the map" : "in an obstacle of the map";
  }
  const double clearance = world_->staticClearance(goal);
  if (clearance <= config_.robot_radius) {
    return std::to_string(clearance) +
           " m from the map's obstacles, within the robot's footprint (" +
           std::to_string(config_.robot_radius) + " m)";
  }
  return "";
}

bool MapPlanner::explainedByMap(const Eigen::Vector2d& p) const {
  return world_->staticClearance(p) < 1.5 * world_->map()->resolution;
}

std::string MapPlanner::plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                             const std::vector<Eigen::Vector2d>& seen,
                             std::vector<Eigen::Vector2d>& path) const {
  path.clear();
  if (const std::string why = checkGoal(goal); !why.empty()) {
    return "the goal " + pointText(goal) + " is " + why;
  }
  // What the scanner sees beyond the map: thin posts the size of a cell.
  std::vector<Obstacle> obstacles;
  for (const Eigen::Vector2d& p : seen) {
    if (!p.allFinite() || explainedByMap(p)) continue;
    Obstacle o;
    o.shape = Obstacle::Shape::kCylinder;
    o.center = p;
    o.radius = 0.5 * kFootprintGridResolution;
    obstacles.push_back(o);
  }
  const FootprintGrid grid(*world_, kFootprintGridResolution, config_.robot_radius, obstacles,
                           config_.clearance);
  if (!grid.isFree(goal)) {
    return "the goal " + pointText(goal) + " is blocked by what the scan sees";
  }
  Eigen::Vector2d from = start;
  if (!grid.isFree(start)) {
    // As far as the footprint's diameter: a robot pushed into a wall's end is that deep in.
    const double reach = 2.0 * config_.robot_radius + grid.resolution();
    const long cell = nearestFreeCell(grid, start, reach);
    if (cell < 0) {
      return "the robot at " + pointText(start) + " has no free cell for its footprint within " +
             std::to_string(reach) + " m";
    }
    from = grid.centre(cell);
  }
  if (!planPath(grid, from, goal, config_.clearance_cost, path)) {
    return "no path for the robot's footprint from " + pointText(start) + " to " + pointText(goal);
  }
  if (from != start) path.insert(path.begin(), start);
  return "";
}

}  // namespace jetbot_rl
