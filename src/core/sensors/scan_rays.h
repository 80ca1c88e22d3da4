#pragma once

// The exact ray tests of the laser scanner (scan_cast.cpp): the distance along a unit ray to an
// obstacle or the map's cells, if it is below `best` (else `best`).

#include <LinearMath/btVector3.h>

#include <Eigen/Geometry>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// To box `b` (its frame: yaw about z at its centre, from the ground up to its height): Bullet's
/// exact ray-AABB test in the box's frame.
double rayBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& b, double best);
/// A ray origin in a box's frame, for casting several rays from it.
struct BoxFrame {
  /// The origin `o` in box `b`'s frame, with cos and sin of its yaw given.
  BoxFrame(const Eigen::Vector3d& o, const Obstacle& b, double cos_yaw, double sin_yaw);
  double c, s;          ///< cos and sin of the box's yaw
  btVector3 from;       ///< the origin in the box's frame
  btVector3 bounds[2];  ///< the box's corners in its frame
};
/// rayBox() from a BoxFrame's origin along `d` (world frame).
double rayBox(const BoxFrame& box, const Eigen::Vector3d& d, double best);
/// To a vertical cylinder: its side, or its top for a beam from above.
double rayCylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& cyl,
                   double best);
/// To the map's obstacle cells (prisms up to `height`): a grid traversal in the map frame
/// (Amanatides and Woo), the distance where the beam enters the first obstacle cell.
double rayMap(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const WorldModel& world,
              double height, double best);

}  // namespace jetbot_rl
