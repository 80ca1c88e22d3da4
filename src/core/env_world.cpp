#include "jetbot_rl/env_world.h"

#include <cmath>
#include <sstream>

namespace jetbot_rl {
namespace {

// Robots collide with the ground only: never with each other's parts.
constexpr int kRobotGroup = btBroadphaseProxy::CharacterFilter;
constexpr int kGroundGroup = btBroadphaseProxy::StaticFilter;
constexpr btScalar kGravity = -9.81;            // [m/s^2]
constexpr btScalar kGroundFriction = 1.0;       // multiplied with each body's friction
constexpr double kMaxPosition = 1000.0;         // [m] from the env origin
constexpr double kMinHeight = -1.0;             // [m]: below means it fell through the ground
constexpr double kMaxLinearVelocity = 100.0;    // [m/s]
constexpr double kMaxAngularVelocity = 1000.0;  // [rad/s]

Eigen::Vector3d toEigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

}  // namespace

EnvWorld::EnvWorld(const PhysicsModel& model, WorkerContext& context)
    : model_(model),
      dispatcher_(new btCollisionDispatcher(&context.collision_configuration)),
      broadphase_(new btSimpleBroadphase(static_cast<int>(model.bodies().size()) + 1)),
      world_(new btDiscreteDynamicsWorld(dispatcher_.get(), broadphase_.get(), &context.solver,
                                         &context.collision_configuration)),
      ground_(new btCollisionObject()),
      targets_(model.dofs().size(), 0.0f) {
  world_->setGravity(btVector3(0, 0, kGravity));
  world_->getSolverInfo().m_numIterations = model.solverIterations();

  ground_->setCollisionShape(const_cast<btCollisionShape*>(model.groundShape()));
  ground_->setFriction(kGroundFriction);
  world_->addCollisionObject(ground_.get(), kGroundGroup, kRobotGroup);

  for (const auto& b : model.bodies()) {
    btRigidBody::btRigidBodyConstructionInfo info(b.mass, nullptr, b.shape, b.inertia);
    info.m_startWorldTransform = b.rest_pose;
    info.m_friction = b.friction;
    auto body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);  // an RL env never sleeps
    world_->addRigidBody(body.get(), kRobotGroup, kGroundGroup);
    bodies_.push_back(std::move(body));
  }
  for (const auto& j : model.joints()) {
    auto hinge = std::make_unique<btHingeConstraint>(*bodies_[j.parent], *bodies_[j.child],
                                                     j.frame_in_parent, j.frame_in_child);
    if (j.limited) hinge->setLimit(j.lower, j.upper);
    world_->addConstraint(hinge.get(), /*disableCollisionsBetweenLinkedBodies=*/true);
    joints_.push_back(std::move(hinge));
  }
}

EnvWorld::~EnvWorld() {
  for (auto& j : joints_) world_->removeConstraint(j.get());
  for (auto& b : bodies_) world_->removeRigidBody(b.get());
  world_->removeCollisionObject(ground_.get());
}

void EnvWorld::reset() {
  const auto& models = model_.bodies();
  for (size_t i = 0; i < bodies_.size(); ++i) {
    btRigidBody& body = *bodies_[i];
    body.setCenterOfMassTransform(models[i].rest_pose);  // also refreshes the world inertia
    body.setLinearVelocity(btVector3(0, 0, 0));
    body.setAngularVelocity(btVector3(0, 0, 0));
    body.setInterpolationLinearVelocity(btVector3(0, 0, 0));
    body.setInterpolationAngularVelocity(btVector3(0, 0, 0));
    body.clearForces();
    world_->updateSingleAabb(&body);
  }
  // Forget contact points so a reset env behaves exactly like a fresh one (no warm start).
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
    dispatcher_->getManifoldByIndexInternal(i)->clearManifold();
  }
  std::fill(targets_.begin(), targets_.end(), 0.0f);
}

void EnvWorld::setTargets(const float* targets) {
  std::copy(targets, targets + targets_.size(), targets_.begin());
}

void EnvWorld::step(double dt) {
  const auto& dofs = model_.dofs();
  for (size_t d = 0; d < dofs.size(); ++d) {
    // Velocity drive: torque = gain * (target - velocity), limited by the effort limit; solved
    // as a velocity constraint so it never overshoots the target (stable at any gain).
    const double error = targets_[d] - dofVelocity(static_cast<int>(d));
    const double torque = std::min(dofs[d].effort_limit, model_.driveGain() * std::abs(error));
    // Bullet's hinge motor drives (w_parent - w_child) . axis, the opposite of URDF's sign.
    joints_[dofs[d].joint]->enableAngularMotor(true, -targets_[d],
                                               static_cast<btScalar>(torque * dt));
  }
  world_->stepSimulation(static_cast<btScalar>(dt), 0);
}

RootState EnvWorld::rootState() const {
  const btRigidBody& root = *bodies_[0];
  const btTransform link = linkPose(0);
  const btQuaternion q = link.getRotation();
  RootState s;
  s.position = toEigen(link.getOrigin());
  s.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
  s.com_linear_velocity = toEigen(root.getLinearVelocity());
  s.angular_velocity = toEigen(root.getAngularVelocity());
  return s;
}

void EnvWorld::setRootState(const RootState& state) {
  const btTransform old_link = linkPose(0);
  const btVector3 old_omega = bodies_[0]->getAngularVelocity();
  const Eigen::Quaterniond q = state.orientation.normalized();
  const btTransform new_link(btQuaternion(q.x(), q.y(), q.z(), q.w()), toBullet(state.position));
  const btTransform delta = new_link * old_link.inverse();
  const btVector3 omega = toBullet(state.angular_velocity);
  const btVector3 root_com = delta * bodies_[0]->getWorldTransform().getOrigin();
  for (auto& body : bodies_) {
    const btTransform pose = delta * body->getWorldTransform();
    const btVector3 spin = body->getAngularVelocity() - old_omega;  // wheels keep spinning
    body->setCenterOfMassTransform(pose);
    body->setLinearVelocity(toBullet(state.com_linear_velocity) +
                            omega.cross(pose.getOrigin() - root_com));
    body->setAngularVelocity(omega + delta.getBasis() * spin);
    world_->updateSingleAabb(body.get());
  }
}

std::string EnvWorld::divergence() const {
  const auto& models = model_.robot().bodies();
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const btRigidBody& body = *bodies_[i];
    const btVector3& p = body.getWorldTransform().getOrigin();
    const btVector3& v = body.getLinearVelocity();
    const btVector3& w = body.getAngularVelocity();
    std::ostringstream why;
    why << "link '" << models[i].link_name << "' ";
    if (!std::isfinite(p.length2()) || !std::isfinite(v.length2()) || !std::isfinite(w.length2()) ||
        !std::isfinite(body.getWorldTransform().getBasis()[0].length2())) {
      why << "has a non-finite state";
    } else if (p.length() > kMaxPosition) {
      why << "is " << p.length() << " m from its env origin (limit " << kMaxPosition << " m)";
    } else if (p.z() < kMinHeight) {
      why << "fell through the ground (z = " << p.z() << " m)";
    } else if (v.length() > kMaxLinearVelocity) {
      why << "moves at " << v.length() << " m/s (limit " << kMaxLinearVelocity << " m/s)";
    } else if (w.length() > kMaxAngularVelocity) {
      why << "spins at " << w.length() << " rad/s (limit " << kMaxAngularVelocity << " rad/s)";
    } else {
      continue;
    }
    return why.str();
  }
  return {};
}

double EnvWorld::maxJointError() const {
  double worst = 0.0;
  const auto& joints = model_.joints();
  for (const auto& j : joints) {
    const btVector3 a = bodies_[j.parent]->getWorldTransform() * j.frame_in_parent.getOrigin();
    const btVector3 b = bodies_[j.child]->getWorldTransform() * j.frame_in_child.getOrigin();
    worst = std::max(worst, static_cast<double>((a - b).length()));
  }
  return worst;
}

double EnvWorld::dofVelocity(int dof) const {
  const auto& j = model_.joints()[model_.dofs()[dof].joint];
  const btRigidBody& parent = *bodies_[j.parent];
  const btRigidBody& child = *bodies_[j.child];
  const btVector3 axis =
      child.getWorldTransform().getBasis() * j.frame_in_child.getBasis().getColumn(2);
  return (child.getAngularVelocity() - parent.getAngularVelocity()).dot(axis);
}

btTransform EnvWorld::linkPose(int body) const {
  return bodies_[body]->getWorldTransform() * model_.bodies()[body].com_in_link.inverse();
}

}  // namespace jetbot_rl
