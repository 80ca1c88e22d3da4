#pragma once

#include <Eigen/Core>
#include <vector>

#include "jetbot_rl/planning/footprint_grid.h"

namespace jetbot_rl {

/**
 * The global planner: the cheapest path for the robot's centre from `start` to `goal` over the
 * free cells of `grid` (the occupancy inflated by the footprint), by A* over 8 neighbours without
 * cutting a blocked corner. A step costs its length x (1 + `clearance_cost` x (1 - c)), c the
 * cell's clearance beyond the footprint as a share of the grid's margin (costmap_2d's inflation
 * cost, linear): paths keep off walls where there is room. The cells' path is then straightened
 * (string pulling: from each kept point on to the farthest cell in sight over cells no nearer the
 * walls than the stretch it replaces). Writes the start, the corners and the goal to `path`;
 * false (and `path` empty) when the start or the goal is not free or no path joins them. Ties
 * broken by cell index: deterministic.
 */
bool planPath(const FootprintGrid& grid, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
              double clearance_cost, std::vector<Eigen::Vector2d>& path);

}  // namespace jetbot_rl
