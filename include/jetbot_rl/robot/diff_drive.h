#pragma once

#include <array>
#include <string>
#include <vector>

#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

class BatchedEnv;

/// One wheel of a differential drive.
struct DriveWheel {
  std::string joint;            ///< The dof joint's name.
  int dof = 0;                  ///< Its index in dof_names (action order), 0 or 1.
  double direction = 1.0;       ///< +1: a positive joint velocity rolls it forward (root +x).
  double velocity_limit = 0.0;  ///< [rad/s]
};

/// A planar body velocity in the root frame (REP 103: x forward, z up).
struct PlanarTwist {
  double linear = 0.0;   ///< Along root +x [m/s].
  double angular = 0.0;  ///< About root +z, counter-clockwise positive [rad/s].
};

/**
 * Differential-drive kinematics of two wheel dofs: body twist <-> wheel joint velocities.
 *
 * fromRobot() derives the wheel radius (the wheels' collision radius about their joint axis) and
 * separation (the distance between the two joints along their axis) from the URDF, which wheel is
 * left (the larger y in the root frame) and which way each one turns to drive forward (its axis
 * as the URDF states it, whatever its joint frame's rotation).
 */
class DiffDrive {
 public:
  /// Throws ConfigError naming a radius [m], separation [m] or wheel velocity limit [rad/s] that
  /// is not positive and finite, or dofs other than 0 and 1.
  DiffDrive(double wheel_radius, double wheel_separation, DriveWheel left, DriveWheel right);

  /**
   * Derives the kinematics of `robot` driven by `dof_names` (exactly two joints) with their
   * velocity limits [rad/s]. A positive `wheel_radius` / `wheel_separation` [m] is used instead of
   * the derived one. Throws ModelError naming the joint or link when a value cannot be derived,
   * ConfigError for other than two dofs or a negative override.
   */
  static DiffDrive fromRobot(const RobotModel& robot, const std::vector<std::string>& dof_names,
                             const std::vector<double>& velocity_limits, double wheel_radius = 0.0,
                             double wheel_separation = 0.0);
  /// fromRobot() for an env: its robot, dof_names, velocity limits in use (dofLimits()) and
  /// EnvConfig::wheel_radius / wheel_separation.
  static DiffDrive fromEnv(const BatchedEnv& env);

  double wheelRadius() const { return radius_; }          ///< [m]
  double wheelSeparation() const { return separation_; }  ///< [m]
  /// Where the radius and separation come from, e.g. "URDF: collision of 'left_wheel'", or
  /// "parameter".
  const std::string& radiusSource() const { return radius_source_; }
  const std::string& separationSource() const { return separation_source_; }
  const DriveWheel& left() const { return left_; }
  const DriveWheel& right() const { return right_; }

  /// Joint velocity targets [rad/s] in dof order for `twist`; when a wheel would exceed its limit,
  /// both are scaled down by the same factor, which keeps the curvature (a turn stays a turn).
  /// Throws InputError for a non-finite value.
  std::array<double, 2> wheelTargets(const PlanarTwist& twist) const;
  /// Body twist from the two dof velocities [rad/s] in dof order (odometry).
  PlanarTwist bodyTwist(const std::array<double, 2>& dof_velocities) const;
  /// One line for the start-up INFO echo: every value in use and where it comes from.
  std::string describe() const;

 private:
  double radius_;
  double separation_;
  DriveWheel left_, right_;
  std::string radius_source_ = "parameter";
  std::string separation_source_ = "parameter";
};

}  // namespace jetbot_rl
