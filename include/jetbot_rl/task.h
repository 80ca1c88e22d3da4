#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/rng.h"

namespace jetbot_rl {

struct ScannerSpec;
class WorldModel;

/// What a task may use of the batch it runs in, given once before any per-env call.
struct TaskContext {
  const ScannerSpec* scanner = nullptr;  ///< The laser scanner, or none.
  const WorldModel* world = nullptr;     ///< The world, or none.
  int action_dim = 0;
  double control_dt = 0.0;  ///< [s]
};

/// What an env senses besides its root state, for tasks that use it; set before every
/// terminated/reward/observe of the env (pointers valid until its next step).
struct EnvSenses {
  const float* scan = nullptr;  ///< The latest scan (REP 117 values), or none.
  bool collided = false;        ///< The robot touched the world during the last step.
  const float* action =
      nullptr;  ///< The action of the last step (action_dim), zeros after a reset.
};

/// How an ended episode ended, as a task judges it (for success, collision and time-out rates).
enum class Outcome : std::uint8_t {
  kTimeOut = 0,  ///< Truncated (or a task without goals).
  kSuccess = 1,  ///< The task's goal was reached.
  kFailure = 2,  ///< It ended badly (a collision).
};

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
  /// Checks what the task needs of the batch (ConfigError naming what is missing) and keeps
  /// what it uses; called once, before resize().
  virtual void attach(const TaskContext& context) { (void)context; }
  /// Sizes per-env state; called once before any other per-env call.
  virtual void resize(int num_envs) { (void)num_envs; }
  /// At a reset of an env with a world, after its start was drawn and before its obstacles:
  /// draws what the task keeps free of obstacles (a goal) from `rng` and appends its points to
  /// `keep_free`.
  virtual void drawInWorld(int env, Rng& rng, const WorldModel& world, const Eigen::Vector2d& start,
                           std::vector<Eigen::Vector2d>& keep_free) {
    (void)env;
    (void)rng;
    (void)world;
    (void)start;
    (void)keep_free;
  }
  /// Gives env `env`'s senses for the calls that follow (only tasks that need them keep them).
  virtual void sense(int env, const EnvSenses& senses) {
    (void)env;
    (void)senses;
  }
  /// How env `env`'s episode ended, asked right after it ended (before its reset).
  virtual Outcome outcome(int env) const {
    (void)env;
    return Outcome::kTimeOut;
  }
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
  /// Angles [rad, in the scanner's frame] of the scan beams the observation holds, in order: the
  /// geometry a robot elsewhere resamples its own scan to. Empty: the task observes no scan.
  virtual std::vector<double> scanBeamAngles() const { return {}; }
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
