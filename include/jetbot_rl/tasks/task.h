#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/rng.h"

namespace jetbot_rl {

struct CameraSpec;
struct ScannerSpec;
class TaskObserver;
struct ObserverSpec;
class WorldModel;

/// What a task may use of the batch it runs in, given once before any per-env call.
struct TaskContext {
  const ScannerSpec* scanner = nullptr;  ///< The laser scanner, or none.
  const WorldModel* world = nullptr;     ///< The world, or none.
  const CameraSpec* camera = nullptr;    ///< The camera whose images the batch carries, or none.
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
  bool collided_with_mover = false;  ///< A mover (movers/...) was among what it touched.
  bool collided_with_robot = false;  ///< Another robot of its world (robots_per_env) was too.
};

/// How an ended episode ended, as a task judges it (for success, collision and time-out rates).
enum class Outcome : std::uint8_t {
  kTimeOut = 0,         ///< Truncated (or a task without goals).
  kSuccess = 1,         ///< The task's goal was reached.
  kCollision = 2,       ///< The robot hit the world: a wall, the map, an obstacle (navigation).
  kCollisionMover = 3,  ///< The robot hit a mover, a person or a cart (navigation, movers/...).
  kCollisionRobot = 4,  ///< The robot hit another robot of its world (navigation, robots_per_env).
  kWaited = 5,    ///< Not an episode of the task: the row waited for its round to end (rounds).
  kOffTrack = 6,  ///< The robot left the tape (road following): a failure, counted as a collision.
};

/// The rate an ended episode counts in: 0 time-out, 1 success, 2 collision (with the world, a
/// mover or a robot); -1 for a round's wait (kWaited), which is no episode and counts in none.
inline int outcomeRate(std::uint8_t outcome) {
  if (outcome == static_cast<std::uint8_t>(Outcome::kWaited)) return -1;
  return outcome < 2 ? outcome : 2;
}

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
 * Observation, reward and termination of an RL task, apart from the stepping code: what every
 * task has. What only some tasks do (take a command, draw into the world, draw arrows) are
 * capabilities a task opts into by deriving from them (task_capabilities.h).
 *
 * Called concurrently for different envs from the stepping threads: an implementation keeps
 * per-env state in per-env slots only.
 */
class Task {
 public:
  virtual ~Task() = default;
  /// Name as given to the `task` parameter.
  virtual std::string name() const = 0;
  /// How the task observes: its observation's names, bounds and values, from a measured state
  /// (the same code a robot elsewhere observes with).
  virtual const TaskObserver& observer() const = 0;
  /// One name per observation component (the observer's).
  std::vector<std::string> observationNames() const;
  /// Writes the task's part of the observation contract (observer_spec.h: its scan beams, their
  /// range and scale, goal radius, path settings) into `spec`, from which makeObserver() builds
  /// the observer the task observes with; after attach(). The env writes the robot's part.
  virtual void describeObservation(ObserverSpec& spec) const { (void)spec; }
  /// Checks what the task needs of the batch (ConfigError naming what is missing) and keeps
  /// what it uses; called once, before resize().
  virtual void attach(const TaskContext& context) { (void)context; }
  /// Sizes per-env state; called once before any other per-env call.
  virtual void resize(int num_envs) { (void)num_envs; }
  /// Called whenever env `env` is reset, after its root state was reset.
  virtual void resetEnv(int env, Rng& rng) {
    (void)env;
    (void)rng;
  }
  /// Gives env `env`'s senses for the calls that follow (only tasks that need them keep them).
  virtual void sense(int env, const EnvSenses& senses) {
    (void)env;
    (void)senses;
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
  /// How env `env`'s episode ended, asked right after it ended (before its reset).
  virtual Outcome outcome(int env) const {
    (void)env;
    return Outcome::kTimeOut;
  }
};

/// `task` as capability C (task_capabilities.h), or nullptr when it does not have it.
template <class C>
C* capability(Task& task) {
  return dynamic_cast<C*>(&task);
}
template <class C>
const C* capability(const Task& task) {
  return dynamic_cast<const C*>(&task);
}

}  // namespace jetbot_rl
