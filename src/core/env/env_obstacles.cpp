// An env's obstacles in its Bullet world (EnvPhysics): a collision object per obstacle slot, or
// beyond 32 slots one static compound shape remade at each layout.
#include "env/env_physics.h"

namespace jetbot_rl {
btCollisionShape* EnvPhysics::parkedShape(btTransform& pose,
                                          std::vector<std::unique_ptr<btCollisionShape>>& owner) {
  Obstacle parked;
  parked.half_extents = {0.1, 0.1};
  parked.height = 0.1;
  owner.push_back(makeObstacleShape(parked, pose));
  pose.getOrigin().setZ(kParked);
  return owner.back().get();
}

void EnvPhysics::parkObstacles(btCompoundShape& compound) {
  // An empty compound has no AABB: a placeholder far below the ground stands in.
  btTransform pose;
  btCollisionShape* shape = parkedShape(pose, obstacle_shapes_);
  compound.addChildShape(pose, shape);
}

void EnvPhysics::setObstacles(const std::vector<Obstacle>& obstacles) {
  if (obstacle_compound_) {
    // A new compound of the placed obstacles; the old one goes once nothing points at it.
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(obstacles.size()));
    for (const Obstacle& o : obstacles) {
      if (!o.placed) continue;
      btTransform pose;
      shapes.push_back(makeObstacleShape(o, pose));
      compound->addChildShape(pose, shapes.back().get());
    }
    btCollisionObject& object = *obstacles_.front();
    world_->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
        object.getBroadphaseHandle(), dispatcher_.get());
    std::swap(obstacle_shapes_, shapes);
    if (compound->getNumChildShapes() == 0) parkObstacles(*compound);
    object.setCollisionShape(compound.get());
    world_->updateSingleAabb(&object);
    obstacle_compound_ = std::move(compound);
    return;
  }
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    btCollisionObject& object = *obstacles_[i];
    btTransform pose;
    if (i < obstacles.size() && obstacles[i].placed) {
      obstacle_shapes_[i] = makeObstacleShape(obstacles[i], pose);
    } else {
      pose = object.getWorldTransform();
      pose.getOrigin().setZ(kParked);
    }
    // Its old contacts go with its old shape.
    world_->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
        object.getBroadphaseHandle(), dispatcher_.get());
    object.setCollisionShape(obstacle_shapes_[i].get());
    object.setWorldTransform(pose);
    world_->updateSingleAabb(&object);
  }
}

}  // namespace jetbot_rl
