#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/physics_model.h"
#include "jetbot_rl/task.h"

namespace jetbot_rl {

/// Scratch shared by the worlds one thread steps: Bullet's pools and solver are not thread-safe,
/// and carry no state from one world's step to the next.
struct WorkerContext {
  btDefaultCollisionConfiguration collision_configuration;
  btSequentialImpulseConstraintSolver solver;
};

/**
 * One env's mutable physics state: its own Bullet world in the env's local frame, so that an env
 * never interacts with another and its trajectory does not depend on its origin or on the batch.
 */
class EnvWorld {
 public:
  EnvWorld(const PhysicsModel& model, WorkerContext& context);
  ~EnvWorld();
  EnvWorld(const EnvWorld&) = delete;
  EnvWorld& operator=(const EnvWorld&) = delete;

  /// Puts every body at its rest pose with zero velocity and forgets contacts.
  void reset();
  /// Sets the dof velocity targets [rad/s], already clamped to the joint limits.
  void setTargets(const float* targets);
  /// Applies the velocity drive and advances physics by dt [s].
  void step(double dt);
  /// Root body state in the env frame.
  RootState rootState() const;
  /// Overwrites the root pose and velocity; other bodies move rigidly with the root.
  void setRootState(const RootState& state);
  /// Empty when the state is sane, otherwise why it is not (non-finite or absurd values).
  std::string divergence() const;
  /// Largest distance between a joint's anchor seen from the parent and from the child [m].
  double maxJointError() const;
  /// Velocity of dof `dof` [rad/s]: child relative to parent about the joint axis.
  double dofVelocity(int dof) const;
  /// Pose of body `body`'s link frame in the env frame.
  btTransform linkPose(int body) const;

 private:
  const PhysicsModel& model_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::unique_ptr<btCollisionObject> ground_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btHingeConstraint>> joints_;
  std::vector<float> targets_;
};

}  // namespace jetbot_rl
