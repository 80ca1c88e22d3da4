// An env's movers and the other robots of its world in its Bullet world (EnvPhysics): kinematic
// rigid bodies. Bullet derives a kinematic body's velocity from its last two poses, so that a
// mover pushes the robot as it walks; nothing pushes a mover.
#include "env/env_physics.h"
#include "world/world_shapes.h"

namespace jetbot_rl {

void EnvPhysics::addKinematic(int count, int user_index) {
  for (int k = 0; k < count; ++k) {
    // A placeholder shape of its own (the obstacles' are remade with their layouts).
    btTransform pose;
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, parkedShape(pose, mover_shapes_));
    auto body = std::make_unique<btRigidBody>(info);
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    body->forceActivationState(ISLAND_SLEEPING);
    body->setUserIndex(user_index);
    body->setWorldTransform(pose);
    body->setInterpolationWorldTransform(pose);
    // The other robots' stand-ins enter the world when near (moveKinematic()).
    if (!isStandIn(movers_.size())) world_->addRigidBody(body.get(), kWorldGroup, kRobotGroup);
    movers_.push_back(std::move(body));
    mover_awake_.push_back(0);
  }
}

void EnvPhysics::park(std::size_t k) {
  btRigidBody& body = *movers_[k];
  if (isStandIn(k)) {
    // The other robots' stand-ins are many and mostly far: each object of a Bullet world costs
    // every pass over its objects (a cache miss each, at every physics step), so a parked
    // stand-in leaves the world.
    if (mover_awake_[k]) world_->removeRigidBody(&body);
    return;
  }
  btTransform pose = body.getWorldTransform();
  pose.getOrigin().setZ(kParked);
  body.setWorldTransform(pose);
  body.setInterpolationWorldTransform(pose);
  body.forceActivationState(ISLAND_SLEEPING);  // asleep, Bullet keeps its AABB: set it here
  world_->updateSingleAabb(&body);
}

void EnvPhysics::setKinematic(std::size_t first, std::size_t count,
                              const std::vector<Obstacle>& shapes) {
  for (std::size_t k = 0; k < count; ++k) {
    btRigidBody& body = *movers_[first + k];
    if (k < shapes.size() && shapes[k].placed) {
      btTransform pose;
      mover_shapes_[first + k] = makeObstacleShape(shapes[k], pose);
      body.setCollisionShape(mover_shapes_[first + k].get());
    }
    if (body.getBroadphaseHandle()) {
      world_->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
          body.getBroadphaseHandle(), dispatcher_.get());
    }
    body.setLinearVelocity(btVector3(0, 0, 0));
    body.setAngularVelocity(btVector3(0, 0, 0));
    // Parked until it comes near the robot (moveKinematic()).
    park(first + k);
    mover_awake_[first + k] = 0;
  }
}

void EnvPhysics::moveKinematic(std::size_t first, std::size_t count,
                               const std::vector<Obstacle>& bodies,
                               const std::vector<std::uint8_t>& near) {
  for (std::size_t k = 0; k < count && k < bodies.size(); ++k) {
    btRigidBody& body = *movers_[first + k];
    std::uint8_t& awake = mover_awake_[first + k];
    if (!bodies[k].placed || !near[k]) {
      // Out of the robot's reach: parked, so that no body stays where it walked away from.
      if (awake) park(first + k);
      awake = 0;
      continue;
    }
    const Obstacle& m = bodies[k];
    btTransform& pose = body.getWorldTransform();
    if (!awake) {
      // Where it is now, at rest: the jump from where it was parked is no velocity.
      pose = planar(m.center, m.yaw, 0.5 * m.height);
      body.setInterpolationWorldTransform(pose);
      if (isStandIn(first + k)) world_->addRigidBody(&body, kWorldGroup, kRobotGroup);
      body.forceActivationState(DISABLE_DEACTIVATION);
      awake = 1;
      continue;
    }
    // A person's rotation never changes; a cart's with its heading.
    pose.setOrigin(btVector3(static_cast<btScalar>(m.center.x()),
                             static_cast<btScalar>(m.center.y()),
                             static_cast<btScalar>(0.5 * m.height)));
    if (m.shape == Obstacle::Shape::kBox) {
      pose.setRotation(btQuaternion(btVector3(0, 0, 1), static_cast<btScalar>(m.yaw)));
    }
  }
}

}  // namespace jetbot_rl
