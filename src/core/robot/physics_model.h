#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/robot/dof_limits.h"
#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

/**
 * The Bullet side of the robot: collision shapes, masses and joint frames, built once from a
 * RobotModel and shared read-only by every env (MuJoCo's mjModel to EnvPhysics's mjData).
 */
class PhysicsModel {
 public:
  struct Body {
    btCollisionShape* shape = nullptr;  ///< Owned by shapes_.
    btScalar mass = 0;                  ///< [kg]
    btVector3 inertia{0, 0, 0};         ///< Principal moments [kg m^2].
    btTransform com_in_link;            ///< Principal inertia frame in the link frame.
    btTransform rest_pose;              ///< COM frame in the env frame at rest.
    btScalar friction = 0;              ///< Coulomb friction coefficient with the ground.
    bool driven = false;                ///< A dof joint drives it (a wheel).
    btScalar ground_depth = 0;  ///< Height of its COM above its shape's lowest point at rest [m].
  };
  /// A revolute joint in btMultiBody's terms; frames are the bodies' principal COM frames.
  struct Joint {
    int parent = 0;                    ///< Body index of the parent.
    int child = 0;                     ///< Body index of the child.
    btQuaternion rot_parent_to_child;  ///< Rotates parent-frame vectors into the child frame.
    btVector3 axis_in_child;           ///< Unit joint axis in the child frame.
    btVector3 parent_com_to_pivot;     ///< In the parent frame [m].
    btVector3 pivot_to_child_com;      ///< In the child frame [m].
    bool limited = false;
    btScalar lower = 0, upper = 0;  ///< [rad]
  };
  /// A driven joint: its limits (name, velocity_limit [rad/s], effort_limit [N m], sources).
  struct Dof : DofLimits {
    int joint = 0;  ///< Index into joints().
  };

  /// Friction of bodies driven by a dof joint (rubber tyre on a floor); every other body (the
  /// chassis and its caster) gets EnvConfig::caster_friction.
  static constexpr btScalar kWheelFriction = 1.0;
  /// Collision margin of boxes, kept inside their URDF size [m]. Mesh hulls have none, so that
  /// they touch the ground where their vertices are.
  static constexpr btScalar kCollisionMargin = 0.001;
  /// Cylinder edge rounding as a fraction of min(radius, half length), kept inside the URDF size.
  static constexpr btScalar kTreadRounding = 1.0;
  /// Contact breaking threshold of round shapes (spheres, cylinders) [m].
  static constexpr btScalar kRollingContactBreakingThreshold = 1e-4;

  /// Throws ModelError naming a dof joint the URDF lacks, or whose limits are unusable and the
  /// parameter that would give them.
  PhysicsModel(RobotModelConstPtr robot, const EnvConfig& config);
  ~PhysicsModel();
  PhysicsModel(const PhysicsModel&) = delete;
  PhysicsModel& operator=(const PhysicsModel&) = delete;

  const RobotModel& robot() const { return *robot_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<Dof>& dofs() const { return dofs_; }
  const btCollisionShape* groundShape() const { return ground_.get(); }
  /// Bullet's table of collision algorithm factories, shared by every env and only read (no
  /// pools are used: each env allocates its own manifolds and algorithms).
  btCollisionConfiguration* collisionConfiguration() const {
    return collision_configuration_.get();
  }
  double driveGain() const { return drive_gain_; }
  /// True when the wheels' drives are velocity loops (EnvConfig::drive, auto resolved).
  bool velocityLoop() const { return velocity_loop_; }
  int solverIterations() const { return solver_iterations_; }
  /// True when the wheels' shapes are scaled per env (wheel_radius_scale is not [1, 1]).
  bool scalesWheels() const { return scales_wheels_; }
  /// A new shape: body `body`'s (convex) shape scaled by `scale` about its centre of mass.
  std::unique_ptr<btCollisionShape> makeScaledShape(int body, btScalar scale) const;

 private:
  btCollisionShape* makeShape(const BodyModel& body, const btTransform& com_in_link);

  RobotModelConstPtr robot_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btCollisionShape> ground_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_configuration_;
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<Dof> dofs_;
  double drive_gain_;
  bool velocity_loop_ = false;
  int solver_iterations_;
  bool scales_wheels_ = false;
};

}  // namespace jetbot_rl
