#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/rng.h"

namespace jetbot_rl {

/// Kinematic state of an env's root body, in the env's own frame (origin at the env origin).
struct RootState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               ///< Root link frame origin [m].
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< Root link frame.
  Eigen::Vector3d com_linear_velocity = Eigen::Vector3d::Zero();    ///< COM velocity [m/s].
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       ///< [rad/s].

  /// Centre-of-mass linear velocity in the root body frame (Isaac Lab's root_com_lin_vel_b) [m/s].
  Eigen::Vector3d comLinearVelocityBody() const {
    return orientation.conjugate() * com_linear_velocity;
  }
};

/**
 * Observation, reward and termination of an RL task, apart from the stepping code.
 *
 * Called concurrently for different envs from the stepping threads: an implementation keeps
 * per-env state in per-env slots only.
 */
class Task {
 public:
  virtual ~Task() = default;
  /// Name as given to the `task` parameter.
  virtual std::string name() const = 0;
  /// One name per observation component.
  virtual std::vector<std::string> observationNames() const = 0;
  /// Sizes per-env state; called once before any other per-env call.
  virtual void resize(int num_envs) { (void)num_envs; }
  /// Called whenever env `env` is reset, after its root state was reset.
  virtual void resetEnv(int env, Rng& rng) {
    (void)env;
    (void)rng;
  }
  /// Writes observationNames().size() values to `obs`.
  virtual void observe(int env, const RootState& state, float* obs) const = 0;
  /// Reward of a control step, on the state after physics, before any reset.
  virtual float reward(int env, const RootState& state) const = 0;
  /// True when the env reached a terminal state.
  virtual bool terminated(int env, const RootState& state) const {
    (void)env;
    (void)state;
    return false;
  }

  /// Size of the command a user can set per env (SetCommand's x, y); 0: the task takes none.
  virtual int commandDim() const { return 0; }
  /// Sets env `env`'s command (`commandDim()` values), kept across its resets when `hold`;
  /// throws InputError naming the env and value when invalid, or when the task takes none.
  virtual void setCommand(int env, const std::vector<double>& command, bool hold) {
    (void)env;
    (void)command;
    (void)hold;
    throw InputError("task '" + name() + "' takes no command");
  }
  /// Names of the directions to draw per env besides the robot's forward arrow (marker
  /// namespaces), one per arrowDirection() index.
  virtual std::vector<std::string> arrowNames() const { return {}; }
  /// Unit direction `arrow` of env `env` in the env frame's ground plane.
  virtual Eigen::Vector2d arrowDirection(int env, int arrow) const {
    (void)env;
    (void)arrow;
    return Eigen::Vector2d::UnitX();
  }
};

/// The seed task: observation is the body-frame COM velocity, reward its norm, never terminal.
class VelocityTask : public Task {
 public:
  std::string name() const override { return "velocity"; }
  std::vector<std::string> observationNames() const override {
    return {"lin_vel_b_x", "lin_vel_b_y", "lin_vel_b_z"};
  }
  void observe(int env, const RootState& state, float* obs) const override;
  float reward(int env, const RootState& state) const override;
};

}  // namespace jetbot_rl
