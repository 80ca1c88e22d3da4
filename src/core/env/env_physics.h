#pragma once

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <string>
#include <vector>

#include "env/lean_dispatcher.h"
#include "jetbot_rl/env/randomization.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/world/world_model.h"
#include "robot/physics_model.h"
#include "world/world_shapes.h"

namespace jetbot_rl {

// Robots collide with the ground and the world (map, walls, obstacles, movers): never with each
// other's parts; the world's parts never with each other.
constexpr int kRobotGroup = btBroadphaseProxy::CharacterFilter;
constexpr int kGroundGroup = btBroadphaseProxy::StaticFilter;
constexpr int kWorldGroup = 64;
constexpr int kWorldUserIndex = 1;  // marks the world's static collision objects
constexpr int kMoverUserIndex = 2;  // marks the movers' kinematic bodies
constexpr int kPeerUserIndex = 3;   // marks the other robots' kinematic stand-ins
// Where an obstacle or a mover left out of an episode waits, far below the ground.
constexpr btScalar kParked = -1000;

/// Scratch of one stepping thread, lent to whichever world it steps (EnvPhysics::useContext): the
/// solver is not thread-safe and carries no state from one world's step to the next. Aligned so
/// that two threads' solvers, written on every iteration, never share a cache line.
struct alignas(64) WorkerContext {
  btMultiBodyConstraintSolver solver;
};

/**
 * One env's mutable physics state: its own Bullet world in the env's local frame, so that an env
 * never interacts with another and its trajectory does not depend on its origin or on the batch.
 * The robot is a btMultiBody (Featherstone, reduced coordinates): joints cannot drift apart and
 * the light wheels on the heavy chassis need no extra solver iterations.
 */
class EnvPhysics {
 public:
  /// With `shapes`, the world's static geometry (map, walls) is added, `num_obstacles`
  /// obstacle slots for setObstacles(), `num_movers` kinematic bodies for setMovers() and
  /// `num_peers` for setPeers() (the other robots of its world).
  EnvPhysics(const PhysicsModel& model, WorkerContext& context, const WorldShapes* shapes = nullptr,
             int num_obstacles = 0, int num_movers = 0, int num_peers = 0);
  ~EnvPhysics();
  EnvPhysics(const EnvPhysics&) = delete;
  EnvPhysics& operator=(const EnvPhysics&) = delete;

  /// Puts the robot at its rest pose with zero velocity and forgets contacts.
  void reset();
  /// After reset(): applies `draw` (mass, friction, drive, wheel size, heading and speed; bigger
  /// wheels lift the robot so that they start on the ground). `wheel_spin` [rad/m]: per dof, the
  /// joint velocity per m/s of forward speed at wheel_radius_scale 1 (empty: speed 0).
  void randomize(const RandomizationDraw& draw, const std::vector<double>& wheel_spin);
  /// Moves the robot by `offset` in the ground plane, keeping its heading and velocities (the
  /// world's start, after reset() and randomize()).
  void moveRobot(const Eigen::Vector2d& offset);
  /// Places the obstacles of a layout (as many as the slots; one not placed is left out).
  void setObstacles(const std::vector<Obstacle>& obstacles);
  /// Gives the movers their shapes for an episode (as many as num_movers; one not placed is
  /// left out); they wait parked until moveMovers() finds them near the robot.
  void setMovers(const std::vector<Obstacle>& movers) { setKinematic(0, num_movers_, movers); }
  /// Moves the movers marked in `near` to their poses at the end of the next physics step: it
  /// pushes the robot with the velocity that takes them there. The others are parked below the
  /// ground, asleep (no work at a physics step), until they are near again.
  void moveMovers(const std::vector<Obstacle>& movers, const std::vector<std::uint8_t>& near) {
    moveKinematic(0, num_movers_, movers, near);
  }
  /// The other robots of its world, as movers are: their footprints (as many as num_peers),
  /// parked until movePeers() finds them near.
  void setPeers(const std::vector<Obstacle>& peers) {
    setKinematic(num_movers_, movers_.size() - num_movers_, peers);
  }
  /// Moves the other robots' stand-ins as moveMovers() moves the movers: those marked in `near`
  /// (the others' poses are not read) and the parking of those no longer near.
  void movePeers(const std::vector<Obstacle>& peers, const std::vector<std::uint8_t>& near) {
    moveKinematic(num_movers_, movers_.size() - num_movers_, peers, near);
  }
  /// True when the robot touched the map, a wall, an obstacle, a mover or another robot in a
  /// physics step since the last clearCollided() (reset() clears it too).
  bool collided() const { return collided_ || hit_mover_ || hit_peer_; }
  /// True when one of those touches was with a mover.
  bool collidedWithMover() const { return hit_mover_; }
  /// True when one of those touches was with another robot.
  bool collidedWithPeer() const { return hit_peer_; }
  void clearCollided() { collided_ = hit_mover_ = hit_peer_ = false; }
  /// Makes the next step()s use `context`'s solver (the stepping thread's own).
  void useContext(WorkerContext& context);
  /// Sets the dof velocity targets [rad/s], already clamped to the joint limits.
  void setTargets(const float* targets);
  /// Applies the velocity drive and advances physics by dt [s].
  void step(double dt);
  /// Root body state in the env frame.
  RootState rootState() const;
  /// Overwrites the root pose and velocity; joint positions and velocities are kept.
  void setRootState(const RootState& state);
  /// Stops the robot where it is: the root's and the joints' velocities 0.
  void stop();
  /// Empty when the state is sane, otherwise why it is not (non-finite or absurd values).
  std::string divergence() const;
  /// Largest distance between a joint's anchor seen from the parent and from the child [m].
  double maxJointError() const;
  /// Velocity of dof `dof` [rad/s]: child relative to parent about the joint axis.
  double dofVelocity(int dof) const;
  /// Pose of body `body`'s link frame in the env frame.
  btTransform linkPose(int body) const;
  /// Position [rad] of the joint from body `body`'s parent (body >= 1), about its URDF axis.
  double jointPosition(int body) const { return robot_->getJointPos(body - 1); }
  /// Velocity [rad/s] of the joint from body `body`'s parent (body >= 1).
  double jointVelocity(int body) const { return robot_->getJointVel(body - 1); }
  /// Torque the drive of dof `dof` applied in the last physics step [N m] (0 before one).
  double dofEffort(int dof) const;
  /// Velocity of the root link frame's origin [m/s] and angular velocity [rad/s], both in the
  /// root link frame.
  void rootLinkTwist(Eigen::Vector3d& linear, Eigen::Vector3d& angular) const;
  /// Contact points of the last collision detection, and the pairs they belong to.
  int contactPoints(int* pairs = nullptr) const;
  /// The robot's rigid bodies (linkPose()'s range).
  int numBodies() const;

 private:
  /// World transform of body `body`'s principal COM frame.
  btTransform comPose(int body) const;
  void syncColliders();
  /// A placeholder obstacle shape (kept in `owner`) and its `pose` far below the ground.
  static btCollisionShape* parkedShape(btTransform& pose,
                                       std::vector<std::unique_ptr<btCollisionShape>>& owner);
  /// Adds `count` kinematic bodies marked `user_index`, parked until setKinematic().
  void addKinematic(int count, int user_index);
  /// Gives kinematic bodies first.. their `shapes` (one not placed keeps its last) and parks them.
  void setKinematic(std::size_t first, std::size_t count, const std::vector<Obstacle>& shapes);
  /// Moves kinematic bodies first.. to `bodies` where `near`, parks the others.
  void moveKinematic(std::size_t first, std::size_t count, const std::vector<Obstacle>& bodies,
                     const std::vector<std::uint8_t>& near);
  /// True when kinematic body `k` is another robot's stand-in: in the world only while awake.
  bool isStandIn(std::size_t k) const { return k >= num_movers_; }
  /// Puts kinematic body `k` far below the ground, asleep (a mover) or out of the world (another
  /// robot's stand-in): it touches nothing.
  void park(std::size_t k);
  /// Adds a placeholder child far below the ground (a compound needs one for its AABB).
  void parkObstacles(btCompoundShape& compound);
  /// True when a contact of the last collision detection joins the robot and an object marked
  /// `user_index` (the world's or a mover's).
  bool touches(int user_index) const;

  const PhysicsModel& model_;
  WorkerContext* context_;
  std::unique_ptr<LeanDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  std::unique_ptr<btCollisionObject> ground_;
  std::unique_ptr<btMultiBody> robot_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints_;
  std::vector<btMultiBodyJointMotor*> motors_;  // per dof, owned by constraints_
  // Per body when the model scales wheels (else empty): the scaled shape its collider uses.
  std::vector<std::unique_ptr<btCollisionShape>> scaled_shapes_;
  double gain_scale_ = 1.0, effort_scale_ = 1.0;  // of the draw in force
  std::vector<float> targets_;
  std::vector<double> integral_;  // per dof: the velocity loop's integral correction [rad/s]
  double last_dt_ = 0.0;          // [s] of the last step(), for efforts
  bool stepped_ = false;
  // The world's static geometry (shapes shared) and this env's obstacles (shapes its own).
  std::vector<std::unique_ptr<btCollisionObject>> statics_, obstacles_;
  std::vector<std::unique_ptr<btCollisionShape>> obstacle_shapes_;
  // With many obstacle slots: one compound of the placed obstacles (obstacles_ holds its object).
  std::unique_ptr<btCompoundShape> obstacle_compound_;
  // Kinematic bodies (env_movers.cpp): the movers, then the other robots; their shapes, remade
  // at each episode.
  std::size_t num_movers_ = 0;
  std::vector<std::unique_ptr<btRigidBody>> movers_;
  std::vector<std::unique_ptr<btCollisionShape>> mover_shapes_;
  std::vector<std::uint8_t> mover_awake_;  // per mover: moved in the physics steps
  bool collided_ = false, hit_mover_ = false, hit_peer_ = false;
};

}  // namespace jetbot_rl
