#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/world/occupancy_map.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// How a robot's paths are planned on its map: the training's nav/path_* meanings.
struct MapPlannerConfig {
  double robot_radius = 0.0;    ///< The footprint's radius [m].
  double clearance = 0.3;       ///< Paths keep this beyond the footprint where there is room [m].
  double clearance_cost = 2.0;  ///< What a cell at the footprint costs beyond its length.
};

/**
 * A robot's global planner (move_base's global planner, with the training's grid search): paths
 * on a map (an OccupancyGrid as /map serves it; unknown and occupied cells are walls) inflated by
 * the robot's footprint, around the points its scanner sees that the map does not hold
 * (costmap_2d's obstacle layer, cleared at each plan). All points in the map's frame (the frame
 * its origin is given in) [m].
 */
class MapPlanner {
 public:
  /// ConfigError when the map has no free cell for the footprint.
  MapPlanner(const OccupancyMap& map, const MapPlannerConfig& config);

  /// Why `goal` cannot be planned to ("" when it can): outside the map, on an unknown or
  /// occupied cell, or too near the map's obstacles for the footprint.
  std::string checkGoal(const Eigen::Vector2d& goal) const;
  /// The path from `start` to `goal` around the map and the `seen` points (e.g. scan endpoints;
  /// those the map explains are left out): the start, where it turns, the goal. A start the
  /// footprint does not fit (a robot brushing a wall) leaves from the nearest free cell within
  /// the footprint's diameter and a cell. Returns "" and the path, or why there is none (and `path`
  /// empty).
  std::string plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                   const std::vector<Eigen::Vector2d>& seen,
                   std::vector<Eigen::Vector2d>& path) const;
  /// True when `p` lies on the map's obstacles or unknown cells or within 1.5 cells of them:
  /// a scan endpoint there shows nothing new.
  bool explainedByMap(const Eigen::Vector2d& p) const;
  /// The footprint's radius [m].
  double robotRadius() const { return config_.robot_radius; }

 private:
  MapPlannerConfig config_;
  std::shared_ptr<const WorldModel> world_;
};

}  // namespace jetbot_rl
