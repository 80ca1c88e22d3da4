#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// The cell size of the grids a start and a goal are checked and a path planned on [m].
constexpr double kFootprintGridResolution = 0.05;

/**
 * A world's floor (its region) as a grid of cells for the robot's centre: each cell's clearance
 * (distance from its centre to the nearest wall, map obstacle cell or placed obstacle, capped),
 * free where the robot's footprint touches nothing, and which free cells the robot can reach
 * from a start (4-connected). What a start and a goal are checked on, and a path planned on: the
 * occupancy grid inflated by the footprint (costmap_2d's inscribed radius).
 */
class FootprintGrid {
 public:
  /// `world`'s region at `resolution` [m], for a robot of `robot_radius` [m] among `obstacles`;
  /// clearances are known up to robot_radius + max(margin, resolution) [m] (farther reads as
  /// that).
  FootprintGrid(const WorldModel& world, double resolution, double robot_radius,
                const std::vector<Obstacle>& obstacles, double margin = 0.0);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  double robotRadius() const { return robot_radius_; }
  /// The clearance cap: robot_radius + max(margin, resolution) [m].
  double clearanceCap() const { return cap_; }
  /// The cell holding `p`, or -1 outside the grid.
  long cellOf(const Eigen::Vector2d& p) const;
  /// The centre of `cell` [m].
  Eigen::Vector2d centre(long cell) const;
  /// Of `cell`: its centre's clearance, at most clearanceCap() [m].
  double clearance(long cell) const { return clearance_[cell]; }
  /// True when the robot centred in `cell` touches nothing.
  bool isFreeCell(long cell) const { return cell >= 0 && clearance_[cell] > robot_radius_; }
  /// True when the robot centred in the cell of `p` touches nothing.
  bool isFree(const Eigen::Vector2d& p) const { return isFreeCell(cellOf(p)); }
  /// Marks the cells reachable from `start` (false when `start` is not free).
  bool reachFrom(const Eigen::Vector2d& start);
  /// True when `p` is reachable from the last reachFrom()'s start.
  bool reachable(const Eigen::Vector2d& p) const;

 private:
  Eigen::AlignedBox2d area_;
  double resolution_, robot_radius_, cap_;
  int width_, height_;
  std::vector<float> clearance_;
  std::vector<std::uint8_t> reached_;
};

}  // namespace jetbot_rl
