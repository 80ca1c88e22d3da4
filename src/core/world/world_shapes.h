#pragma once

#include <btBulletCollisionCommon.h>

#include <memory>
#include <vector>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// A shape placed in an env's frame.
struct PlacedShape {
  const btCollisionShape* shape;
  btTransform pose;
};

/**
 * The Bullet side of a WorldModel, built once and shared read-only by every env's world: the map's
 * obstacle rectangles as one compound of boxes (its own bounding-volume tree: a robot is tested
 * against the few boxes near it), and the arena walls.
 */
class WorldShapes {
 public:
  explicit WorldShapes(const WorldModel& world);
  WorldShapes(const WorldShapes&) = delete;
  WorldShapes& operator=(const WorldShapes&) = delete;

  /// The map and the walls, each with its pose in the env frame.
  const std::vector<PlacedShape>& statics() const { return statics_; }

 private:
  std::vector<std::unique_ptr<btCollisionShape>> owned_;
  std::vector<PlacedShape> statics_;
};

/// The pose at `center` [m], turned `yaw` [rad] about z, at height `z` [m].
btTransform planar(const Eigen::Vector2d& center, double yaw, double z);

/// A new Bullet shape for obstacle `o` (a box or a vertical cylinder from the ground up), and
/// its pose in the env frame.
std::unique_ptr<btCollisionShape> makeObstacleShape(const Obstacle& o, btTransform& pose);

}  // namespace jetbot_rl
