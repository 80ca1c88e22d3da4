#include "world/world_shapes.h"

namespace jetbot_rl {
namespace {

// Kept inside the geometry's size, as the robot's boxes.
constexpr btScalar kMargin = 0.001;

}  // namespace

btTransform planar(const Eigen::Vector2d& center, double yaw, double z) {
  return btTransform(btQuaternion(btVector3(0, 0, 1), static_cast<btScalar>(yaw)),
                     btVector3(static_cast<btScalar>(center.x()), static_cast<btScalar>(center.y()),
                               static_cast<btScalar>(z)));
}

std::unique_ptr<btCollisionShape> makeObstacleShape(const Obstacle& o, btTransform& pose) {
  const auto half_height = static_cast<btScalar>(0.5 * o.height);
  std::unique_ptr<btConvexInternalShape> shape;
  if (o.shape == Obstacle::Shape::kBox) {
    shape = std::make_unique<btBoxShape>(btVector3(static_cast<btScalar>(o.half_extents.x()),
                                                   static_cast<btScalar>(o.half_extents.y()),
                                                   half_height));
  } else {
    const auto r = static_cast<btScalar>(o.radius);
    shape = std::make_unique<btCylinderShapeZ>(btVector3(r, r, half_height));
  }
  shape->setMargin(kMargin);
  pose = planar(o.center, o.yaw, 0.5 * o.height);
  return shape;
}

WorldShapes::WorldShapes(const WorldModel& world) {
  if (const OccupancyMap* map = world.map(); map && !world.mapRectangles().empty()) {
    auto compound = std::make_unique<btCompoundShape>(
        /*enableDynamicAabbTree=*/true, static_cast<int>(world.mapRectangles().size()));
    const double h = world.config().obstacle_height;
    for (const Eigen::AlignedBox2d& r : world.mapRectangles()) {
      Obstacle cell;
      cell.half_extents = 0.5 * r.sizes();
      cell.center = r.center();
      cell.height = h;
      btTransform pose;
      owned_.push_back(makeObstacleShape(cell, pose));
      compound->addChildShape(pose, owned_.back().get());
    }
    const Eigen::Isometry2d& m = world.mapPose();
    const double yaw = std::atan2(m.linear()(1, 0), m.linear()(0, 0));
    statics_.push_back({compound.get(), planar(m.translation(), yaw, 0.0)});
    owned_.push_back(std::move(compound));
  }
  if (!world.worldObstacles().empty()) {  // a Gazebo world's: one compound, as the map's cells
    auto compound = std::make_unique<btCompoundShape>(
        /*enableDynamicAabbTree=*/true, static_cast<int>(world.worldObstacles().size()));
    for (const Obstacle& o : world.worldObstacles()) {
      btTransform pose;
      owned_.push_back(makeObstacleShape(o, pose));
      compound->addChildShape(pose, owned_.back().get());
    }
    statics_.push_back({compound.get(), btTransform::getIdentity()});
    owned_.push_back(std::move(compound));
  }
  for (const Obstacle& w : world.walls()) {
    btTransform pose;
    owned_.push_back(makeObstacleShape(w, pose));
    statics_.push_back({owned_.back().get(), pose});
  }
}

}  // namespace jetbot_rl
