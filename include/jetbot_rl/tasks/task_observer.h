#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {

/// What a robot measured, all in one frame: the env frame in simulation, the odometry frame on a
/// robot. An observer turns it into the task's observation, the same way in both.
struct MeasuredState {
  RootState root;  ///< Pose and velocities (RootState's conventions: velocities in that frame).
  /// Ranges [m] at the observer's scanBeams() beams, REP 117 values (±inf out of range, NaN as
  /// +inf), or none (every beam at range_max).
  const float* scan = nullptr;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();      ///< The goal [m] (tasks with one).
  Eigen::Vector2d command = Eigen::Vector2d::UnitX();  ///< The unit command (tasks with one).
  const float* last_action = nullptr;  ///< The last action (action_dim values), or none: zeros.
  /// Tasks that follow a path: the path left to the goal [m] and a point along it ahead [m].
  double path_remaining = 0.0;
  Eigen::Vector2d lookahead = Eigen::Vector2d::Zero();
};

/**
 * How a task observes (its observation's layout, bounds and values) and, for a task with a goal,
 * when the goal is reached, from a measured state alone. Each task owns one and observes through
 * it in simulation; a robot elsewhere builds the same from the policy's env spec
 * (makeObserver(), task_factory.h), so the simulated and the real robot share one code path.
 */
class TaskObserver {
 public:
  virtual ~TaskObserver() = default;
  /// One name per observation component.
  virtual std::vector<std::string> observationNames() const = 0;
  /// Per component, the range it stays in (±inf where none is known).
  virtual void observationBounds(std::vector<float>& low, std::vector<float>& high) const;
  /// Beams of the scan it observes (0: none).
  virtual int scanBeams() const { return 0; }
  /// True when it observes a goal (and reached() tells when it is reached).
  virtual bool hasGoal() const { return false; }
  /// True when it observes a command.
  virtual bool takesCommand() const { return false; }
  /// Writes observationNames().size() values to `obs`.
  virtual void observe(const MeasuredState& state, float* obs) const = 0;
  /// True when `state` has reached its goal (tasks with one).
  virtual bool reached(const MeasuredState& state) const {
    (void)state;
    return false;
  }
};

}  // namespace jetbot_rl
