#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/env/randomization.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

class BatchedEnv;

/// Pose of one URDF link in the world frame (env origin included).
struct LinkPose {
  std::string link;
  Eigen::Isometry3d pose;
};

/// One env's moving (revolute and continuous) joints, in BatchedEnv::jointNames() order.
struct JointStates {
  std::vector<double> position;  ///< [rad] about the URDF axis.
  std::vector<double> velocity;  ///< [rad/s].
  std::vector<double> effort;    ///< Drive torque of the last physics step [N m]; 0 if undriven.
};

/// Velocity of a frame, expressed in that frame.
struct BodyTwist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   ///< Of the frame's origin [m/s].
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  ///< [rad/s].
};

/// One env's latest camera images, each row-major from its top left pixel.
struct EnvImages {
  int width = 0, height = 0;            ///< [px]
  const std::uint8_t* rgb = nullptr;    ///< rgb8: height x width x 3
  const float* depth = nullptr;         ///< 32FC1: height x width [m] (REP 118)
  const std::uint8_t* label = nullptr;  ///< height x width SurfaceClass values
};

/**
 * Read-only view of one env of a batch (BatchedEnv::view()): what the ROS views (tf, odom,
 * joint_states, scan, markers) and tests read of it. Valid while the batch lives; what it
 * returns is the state after the batch's last step() or reset().
 */
class EnvView {
 public:
  /// Its row of the batch (with robots_per_env K: robot env() % K of env env() / K).
  int env() const { return env_; }
  /// Origin of the env on the square grid, Isaac Lab's layout [m] (every robot of an env: its).
  Eigen::Vector3d origin() const;
  /// Root state in the env's own frame.
  RootState rootState() const;
  /// Twist of the root link frame, in that frame (odometry's twist; the pose is rootState()'s
  /// position and orientation).
  BodyTwist rootTwist() const;
  /// World pose of every URDF link.
  std::vector<LinkPose> linkPoses() const;
  /// Joint positions, velocities and drive efforts, in BatchedEnv::jointNames() order; the
  /// vectors are resized, so a reused `out` allocates nothing.
  void jointStates(JointStates& out) const;
  /// Velocity of dof `dof` [rad/s]; InputError when out of range.
  double dofVelocity(int dof) const;
  /// Largest anchor separation over the joints [m].
  double maxJointError() const;
  /// The values the env drew at its last reset (docs/core.md, "Domain randomisation"); the
  /// defaults when randomisation is off.
  RandomizationDraw randomization() const;
  /// The layout of its current episode: start and obstacles.
  const EnvLayout& layout() const;
  /// True when the robot touched the map, a wall, an obstacle or a mover during the last step.
  bool collided() const;
  /// Its movers where they stand (movers/...): the people, then the carts; empty without.
  const std::vector<Obstacle>& movers() const;
  /// The latest scan: BatchedEnv::scanner()->samples ranges [m] (REP 117: +inf beyond
  /// range_max, -inf below range_min); nullptr without a scanner.
  const float* scan() const;
  /// True when the env took a new scan in the last step() or reset().
  bool scanned() const;
  /// Camera `camera`'s latest images (BatchedEnv::camera(); a pointer is nullptr for an image the
  /// camera does not make, and all are without that camera).
  EnvImages images(int camera = 0) const;
  /// True when camera `camera` made new images in the last step() or reset().
  bool imaged(int camera = 0) const;
  /// Camera `camera`'s optical frame (z forward, x right, y down) in the env frame when it made
  /// them (the identity without that camera).
  Eigen::Isometry3d cameraPose(int camera = 0) const;

 private:
  friend class BatchedEnv;
  EnvView(const BatchedEnv& batch, int env) : batch_(&batch), env_(env) {}

  const BatchedEnv* batch_;
  int env_;
};

}  // namespace jetbot_rl
