#include "env/env_physics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "robot/bullet_conversions.h"

namespace jetbot_rl {
namespace {

// A contact point this close or closer counts as a collision [m] (Bullet keeps points up to its
// breaking threshold apart).
constexpr btScalar kTouching = 1e-3f;
// The velocity loop's integral gain [1/s] and the largest correction, as a fraction of the
// velocity limit: Bullet's solver leaves a wheel a few per cent below its target at low speed
// (10 iterations do not converge the motor against the tyre's friction), which the integral
// removes within a few tenths of a second.
constexpr double kLoopIntegralGain = 20.0;
constexpr double kLoopMaxCorrection = 0.2;
constexpr btScalar kGravity = -9.81;            // [m/s^2]
constexpr btScalar kGroundFriction = 1.0;       // multiplied with each body's friction
constexpr double kMaxPosition = 1000.0;         // [m] from the env origin
constexpr double kMinHeight = -1.0;             // [m]: below means it fell through the ground
constexpr double kMaxLinearVelocity = 100.0;    // [m/s]
constexpr double kMaxAngularVelocity = 1000.0;  // [rad/s]

btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

// Beyond this many obstacle slots an env's obstacles are the children of one static compound
// shape (its own AABB tree finds the few near the robot) instead of one collision object each:
// Bullet's per-object work at every physics step (AABBs, the pair search, islands) would grow
// with them. Up to it, the obstacles of earlier versions' worlds keep their objects, and their
// trajectories bit for bit.
constexpr int kObstacleObjects = 32;

}  // namespace

EnvPhysics::EnvPhysics(const PhysicsModel& model, WorkerContext& context, const WorldShapes* shapes,
                       int num_obstacles, int num_movers, int num_peers)
    : model_(model),
      context_(&context),
      dispatcher_(new LeanDispatcher(model.collisionConfiguration())),
      broadphase_(num_movers > 0
                      ? static_cast<btBroadphaseInterface*>(new btDbvtBroadphase())
                      : new btSimpleBroadphase(
                            static_cast<int>(model.bodies().size()) + 1 +
                            (shapes ? static_cast<int>(shapes->statics().size()) : 0) +
                            (num_obstacles > kObstacleObjects ? 1 : num_obstacles) + num_peers)),
      world_(new btMultiBodyDynamicsWorld(dispatcher_.get(), broadphase_.get(), &context.solver,
                                          model.collisionConfiguration())),
      ground_(new btCollisionObject()),
      targets_(model.dofs().size(), 0.0f),
      integral_(model.dofs().size(), 0.0) {
  world_->setGravity(btVector3(0, 0, kGravity));
  world_->getSolverInfo().m_numIterations = model.solverIterations();
  // Without warm-starting the joint motors from the last step, 10 iterations leave a parked
  // robot creeping at 1 mm/s (motor and tyre friction never agree); with it, it stands still.
  world_->getSolverInfo().m_solverMode |= SOLVER_USE_ARTICULATED_WARMSTARTING;
  world_->getSolverInfo().m_articulatedWarmstartingFactor = 1.0;

  // Only the robot moves: the AABBs of the ground, the world's statics and the obstacles are
  // recomputed when they are placed (setObstacles), not at every physics step, which costs more
  // than the rest of a step with a few hundred obstacles. Asleep, they still collide with the
  // robot (a pair collides when either side is awake).
  world_->setForceUpdateAllAabbs(false);
  ground_->setCollisionShape(const_cast<btCollisionShape*>(model.groundShape()));
  ground_->setFriction(kGroundFriction);
  ground_->setActivationState(ISLAND_SLEEPING);
  world_->addCollisionObject(ground_.get(), kGroundGroup, kRobotGroup);
  const auto addStatic = [this](btCollisionShape* shape, const btTransform& pose) {
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape);
    object->setWorldTransform(pose);
    object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    object->setFriction(kGroundFriction);
    object->setUserIndex(kWorldUserIndex);
    object->setActivationState(ISLAND_SLEEPING);
    world_->addCollisionObject(object.get(), kWorldGroup, kRobotGroup);
    // Its AABB with the contact threshold around it, as every update gives (adding gives none).
    world_->updateSingleAabb(object.get());
    return object;
  };
  if (shapes) {
    for (const PlacedShape& s : shapes->statics()) {
      statics_.push_back(addStatic(const_cast<btCollisionShape*>(s.shape), s.pose));
    }
    if (num_obstacles > kObstacleObjects) {  // one compound, filled by setObstacles()
      obstacle_compound_ = std::make_unique<btCompoundShape>(true, num_obstacles);
      parkObstacles(*obstacle_compound_);
      obstacles_.push_back(addStatic(obstacle_compound_.get(), btTransform::getIdentity()));
    }
    // Obstacle slots: a placeholder shape until the first layout.
    for (int i = 0; i < (obstacle_compound_ ? 0 : num_obstacles); ++i) {
      btTransform pose;
      btCollisionShape* shape = parkedShape(pose, obstacle_shapes_);
      obstacles_.push_back(addStatic(shape, pose));
    }
  }
  num_movers_ = static_cast<std::size_t>(num_movers);
  addKinematic(num_movers, kMoverUserIndex);
  addKinematic(num_peers, kPeerUserIndex);

  const auto& bodies = model.bodies();
  const int links = static_cast<int>(bodies.size()) - 1;
  robot_ = std::make_unique<btMultiBody>(links, bodies[0].mass, bodies[0].inertia,
                                         /*fixedBase=*/false, /*canSleep=*/false);
  for (const auto& j : model.joints()) {
    const PhysicsModel::Body& child = bodies[j.child];
    robot_->setupRevolute(j.child - 1, child.mass, child.inertia, j.parent - 1,
                          j.rot_parent_to_child, j.axis_in_child, j.parent_com_to_pivot,
                          j.pivot_to_child_com, /*disableParentCollision=*/true);
  }
  robot_->finalizeMultiDof();
  // btMultiBody damps by default and caps joint speeds; the environment wants neither.
  robot_->setLinearDamping(0);
  robot_->setAngularDamping(0);
  robot_->setMaxCoordinateVelocity(1e4);
  robot_->setHasSelfCollision(false);
  world_->addMultiBody(robot_.get(), kRobotGroup, kGroundGroup | kWorldGroup);

  if (model.scalesWheels()) scaled_shapes_.resize(bodies.size());
  for (int b = 0; b <= links; ++b) {
    auto collider = std::make_unique<btMultiBodyLinkCollider>(robot_.get(), b - 1);
    if (model.scalesWheels() && bodies[b].driven) {
      scaled_shapes_[b] = model.makeScaledShape(b, 1.0);
      collider->setCollisionShape(scaled_shapes_[b].get());
    } else {
      collider->setCollisionShape(bodies[b].shape);
    }
    collider->setFriction(bodies[b].friction);
    world_->addCollisionObject(collider.get(), kRobotGroup, kGroundGroup | kWorldGroup);
    if (b == 0) {
      robot_->setBaseCollider(collider.get());
    } else {
      robot_->getLink(b - 1).m_collider = collider.get();
    }
    colliders_.push_back(std::move(collider));
  }
  for (const auto& j : model.joints()) {
    if (!j.limited) continue;
    constraints_.push_back(std::make_unique<btMultiBodyJointLimitConstraint>(
        robot_.get(), j.child - 1, j.lower, j.upper));
  }
  for (const auto& dof : model.dofs()) {
    const int link = model.joints()[dof.joint].child - 1;
    auto motor = std::make_unique<btMultiBodyJointMotor>(robot_.get(), link, 0.0, 0.0);
    motors_.push_back(motor.get());
    constraints_.push_back(std::move(motor));
  }
  for (auto& c : constraints_) world_->addMultiBodyConstraint(c.get());
  reset();
}

EnvPhysics::~EnvPhysics() {
  for (auto& c : constraints_) world_->removeMultiBodyConstraint(c.get());
  for (auto& c : colliders_) world_->removeCollisionObject(c.get());
  world_->removeMultiBody(robot_.get());
  world_->removeCollisionObject(ground_.get());
  for (auto& o : statics_) world_->removeCollisionObject(o.get());
  for (auto& o : obstacles_) world_->removeCollisionObject(o.get());
  for (std::size_t k = 0; k < movers_.size(); ++k) {
    if (!isStandIn(k) || mover_awake_[k]) world_->removeRigidBody(movers_[k].get());
  }
}

void EnvPhysics::moveRobot(const Eigen::Vector2d& offset) {
  btTransform base = robot_->getBaseWorldTransform();
  base.getOrigin() +=
      btVector3(static_cast<btScalar>(offset.x()), static_cast<btScalar>(offset.y()), 0);
  robot_->setBaseWorldTransform(base);
  syncColliders();
}

bool EnvPhysics::touches(int user_index) const {
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher_->getManifoldByIndexInternal(i);
    if (m->getBody0()->getUserIndex() != user_index &&
        m->getBody1()->getUserIndex() != user_index) {
      continue;
    }
    for (int c = 0; c < m->getNumContacts(); ++c) {
      if (m->getContactPoint(c).getDistance() <= kTouching) return true;
    }
  }
  return false;
}

void EnvPhysics::syncColliders() {
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> offsets;
  robot_->updateCollisionObjectWorldTransforms(rotations, offsets);
  for (auto& c : colliders_) world_->updateSingleAabb(c.get());
}

void EnvPhysics::reset() {
  const PhysicsModel::Body& root = model_.bodies()[0];
  robot_->setBaseWorldTransform(root.rest_pose);
  robot_->setBaseVel(btVector3(0, 0, 0));
  robot_->setBaseOmega(btVector3(0, 0, 0));
  for (int l = 0; l < robot_->getNumLinks(); ++l) {
    robot_->setJointPos(l, 0);
    robot_->setJointVel(l, 0);
  }
  robot_->clearForcesAndTorques();
  syncColliders();
  // Forget contact points so a reset env behaves exactly like a fresh one (no warm start).
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
    dispatcher_->getManifoldByIndexInternal(i)->clearManifold();
  }
  if (stepped_) {  // and the motors' warm-start impulses (Bullet sizes them on the first step)
    for (auto& c : constraints_) {
      for (int row = 0; row < c->getNumRows(); ++row) c->internalSetAppliedImpulse(row, 0);
    }
  }
  std::fill(targets_.begin(), targets_.end(), 0.0f);
  std::fill(integral_.begin(), integral_.end(), 0.0);
  collided_ = hit_mover_ = hit_peer_ = false;
}

void EnvPhysics::randomize(const RandomizationDraw& draw, const std::vector<double>& wheel_spin) {
  const auto& bodies = model_.bodies();
  robot_->setBaseMass(static_cast<btScalar>(bodies[0].mass * draw.mass_scale));
  robot_->setBaseInertia(bodies[0].inertia * static_cast<btScalar>(draw.mass_scale));
  gain_scale_ = draw.drive_gain_scale;
  effort_scale_ = draw.effort_limit_scale;
  btScalar lift = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].driven) continue;
    colliders_[b]->setFriction(static_cast<btScalar>(draw.wheel_friction));
    if (scaled_shapes_.empty()) continue;
    const auto scale = static_cast<btScalar>(draw.wheel_radius_scale);
    std::unique_ptr<btCollisionShape> shape = model_.makeScaledShape(static_cast<int>(b), scale);
    colliders_[b]->setCollisionShape(shape.get());
    scaled_shapes_[b] = std::move(shape);
    lift = std::max(lift, (scale - 1) * bodies[b].ground_depth);
  }
  // Turned about the env's z axis through the root link origin, lifted, moving forward.
  const btQuaternion yaw(btVector3(0, 0, 1), static_cast<btScalar>(draw.initial_yaw));
  btTransform base = bodies[0].rest_pose;
  base.getOrigin() += btVector3(0, 0, lift);
  robot_->setBaseWorldTransform(btTransform(yaw) * base);
  robot_->setBaseVel(quatRotate(yaw, btVector3(1, 0, 0)) * draw.initial_speed);
  for (std::size_t d = 0; d < wheel_spin.size(); ++d) {
    const int link = model_.joints()[model_.dofs()[d].joint].child - 1;
    robot_->setJointVel(
        link, static_cast<btScalar>(wheel_spin[d] * draw.initial_speed / draw.wheel_radius_scale));
  }
  syncColliders();
}

void EnvPhysics::useContext(WorkerContext& context) {
  if (&context == context_) return;
  world_->setMultiBodyConstraintSolver(&context.solver);
  context_ = &context;
}

void EnvPhysics::setTargets(const float* targets) {
  std::copy(targets, targets + targets_.size(), targets_.begin());
}

void EnvPhysics::step(double dt) {
  const auto& dofs = model_.dofs();
  const bool loop = model_.velocityLoop();
  for (size_t d = 0; d < dofs.size(); ++d) {
    const double effort = dofs[d].effort_limit * effort_scale_;
    if (loop) {
      // A servo: the target plus its integral correction, with all the torque the motor has.
      motors_[d]->setVelocityTarget(static_cast<btScalar>(targets_[d] + integral_[d]));
      motors_[d]->setMaxAppliedImpulse(static_cast<btScalar>(effort * dt));
      continue;
    }
    // Velocity drive: torque = gain * (target - velocity), limited by the effort limit; solved
    // as a velocity constraint so it never overshoots the target (stable at any gain).
    const double error = targets_[d] - dofVelocity(static_cast<int>(d));
    // The scales are 1 unless randomised (x 1.0 is exact: the same torque bit for bit).
    const double torque = std::min(effort, model_.driveGain() * gain_scale_ * std::abs(error));
    motors_[d]->setVelocityTarget(targets_[d]);
    motors_[d]->setMaxAppliedImpulse(static_cast<btScalar>(torque * dt));
  }
  world_->stepSimulation(static_cast<btScalar>(dt), 0);
  last_dt_ = dt;
  stepped_ = true;
  if (loop) {
    for (size_t d = 0; d < dofs.size(); ++d) {
      const double limit = kLoopMaxCorrection * dofs[d].velocity_limit;
      integral_[d] = std::clamp(
          integral_[d] + kLoopIntegralGain * dt * (targets_[d] - dofVelocity(static_cast<int>(d))),
          -limit, limit);
    }
  }
  if (!statics_.empty() || !obstacles_.empty()) collided_ = collided_ || touches(kWorldUserIndex);
  if (num_movers_ > 0) hit_mover_ = hit_mover_ || touches(kMoverUserIndex);
  if (movers_.size() > num_movers_) hit_peer_ = hit_peer_ || touches(kPeerUserIndex);
}

btTransform EnvPhysics::comPose(int body) const {
  // Colliders carry the poses after the last integration (a link's m_cachedWorldTransform is the
  // one before it).
  return colliders_[body]->getWorldTransform();
}

int EnvPhysics::numBodies() const { return static_cast<int>(model_.bodies().size()); }

btTransform EnvPhysics::linkPose(int body) const {
  return comPose(body) * model_.bodies()[body].com_in_link.inverse();
}

RootState EnvPhysics::rootState() const {
  const btTransform link = linkPose(0);
  const btQuaternion q = link.getRotation();
  RootState s;
  s.position = toEigen(link.getOrigin());
  s.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
  s.com_linear_velocity = toEigen(robot_->getBaseVel());
  s.angular_velocity = toEigen(robot_->getBaseOmega());
  return s;
}

void EnvPhysics::setRootState(const RootState& state) {
  const Eigen::Quaterniond q = state.orientation.normalized();
  const btTransform link(btQuaternion(q.x(), q.y(), q.z(), q.w()), toBullet(state.position));
  robot_->setBaseWorldTransform(link * model_.bodies()[0].com_in_link);
  robot_->setBaseVel(toBullet(state.com_linear_velocity));
  robot_->setBaseOmega(toBullet(state.angular_velocity));
  syncColliders();
}

void EnvPhysics::stop() {
  robot_->setBaseVel(btVector3(0, 0, 0));
  robot_->setBaseOmega(btVector3(0, 0, 0));
  for (int l = 0; l < robot_->getNumLinks(); ++l) robot_->setJointVel(l, 0);
}

std::string EnvPhysics::divergence() const {
  const auto& models = model_.robot().bodies();
  const btVector3 v = robot_->getBaseVel();
  const btVector3 w = robot_->getBaseOmega();
  for (size_t b = 0; b < models.size(); ++b) {
    const btTransform pose = comPose(static_cast<int>(b));
    const btVector3& p = pose.getOrigin();
    const double joint_velocity = b == 0 ? 0.0 : robot_->getJointVel(static_cast<int>(b) - 1);
    // Called every step: a message is formatted only for a body that fails a check.
    const auto why = [&](const auto&... parts) {
      std::ostringstream s;
      s << "link '" << models[b].link_name << "' ";
      (s << ... << parts);
      return s.str();
    };
    if (!std::isfinite(p.length2()) || !std::isfinite(pose.getBasis()[0].length2()) ||
        !std::isfinite(v.length2()) || !std::isfinite(w.length2()) ||
        !std::isfinite(joint_velocity)) {
      return why("has a non-finite state");
    }
    if (p.length() > kMaxPosition) {
      return why("is ", p.length(), " m from its env origin (limit ", kMaxPosition, " m)");
    }
    if (p.z() < kMinHeight) return why("fell through the ground (z = ", p.z(), " m)");
    if (b == 0 && v.length() > kMaxLinearVelocity) {
      return why("moves at ", v.length(), " m/s (limit ", kMaxLinearVelocity, " m/s)");
    }
    if (b == 0 && w.length() > kMaxAngularVelocity) {
      return why("spins at ", w.length(), " rad/s (limit ", kMaxAngularVelocity, " rad/s)");
    }
    if (std::abs(joint_velocity) > kMaxAngularVelocity) {
      return why("joint spins at ", joint_velocity, " rad/s (limit ", kMaxAngularVelocity,
                 " rad/s)");
    }
  }
  return {};
}

double EnvPhysics::maxJointError() const {
  double worst = 0.0;
  for (const auto& j : model_.joints()) {
    const btVector3 from_parent = comPose(j.parent) * j.parent_com_to_pivot;
    const btTransform child = comPose(j.child);
    const btVector3 from_child = child * (-j.pivot_to_child_com);
    worst = std::max(worst, static_cast<double>((from_parent - from_child).length()));
  }
  return worst;
}

int EnvPhysics::contactPoints(int* pairs) const {
  int points = 0;
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
    points += dispatcher_->getManifoldByIndexInternal(i)->getNumContacts();
  }
  if (pairs) *pairs = dispatcher_->getNumManifolds();
  return points;
}

double EnvPhysics::dofEffort(int dof) const {
  btMultiBodyJointMotor* motor = motors_[dof];
  if (!stepped_ || last_dt_ <= 0.0 || motor->getNumRows() < 1) return 0.0;
  return motor->getAppliedImpulse(0) / last_dt_;
}

void EnvPhysics::rootLinkTwist(Eigen::Vector3d& linear, Eigen::Vector3d& angular) const {
  const btTransform link = linkPose(0);
  const btVector3 com = comPose(0).getOrigin();
  const btVector3 omega = robot_->getBaseOmega();
  const btVector3 origin_velocity = robot_->getBaseVel() + omega.cross(link.getOrigin() - com);
  const btMatrix3x3 to_link = link.getBasis().transpose();
  linear = toEigen(to_link * origin_velocity);
  angular = toEigen(to_link * omega);
}

double EnvPhysics::dofVelocity(int dof) const {
  return robot_->getJointVel(model_.joints()[model_.dofs()[dof].joint].child - 1);
}

}  // namespace jetbot_rl
