#pragma once

#include <Eigen/Core>
#include <string>

namespace jetbot_rl {

/// When a goal is given up: move_base's time-out and oscillation parameters.
struct GoalWatchConfig {
  double timeout = 0.0;               ///< A goal not reached by then ends [s]; 0: never.
  double oscillation_timeout = 0.0;   ///< No progress for this long is stuck [s]; 0: never.
  double oscillation_distance = 0.2;  ///< Moving this far is progress [m].
};

/**
 * Watches a robot pursuing a goal, as move_base does: the goal times out after `timeout`, and the
 * robot is stuck when it has not moved `oscillation_distance` from where it last made progress
 * within `oscillation_timeout` (pushing into a wall, turning on the spot, frozen). Times in
 * seconds on any one clock.
 */
class GoalWatch {
 public:
  enum class Verdict { kPursuing, kStuck, kTimedOut };

  explicit GoalWatch(const GoalWatchConfig& config = GoalWatchConfig()) : config_(config) {}
  /// A new goal at `now`, the robot at `p` [m].
  void start(double now, const Eigen::Vector2d& p);
  /// Progress counts from `p` at `now` again (after a recovery); the time-out keeps running.
  void restartProgress(double now, const Eigen::Vector2d& p);
  /// The verdict on the robot at `p` at `now`; `why` says it for kStuck and kTimedOut.
  Verdict check(double now, const Eigen::Vector2d& p, std::string& why);
  /// Seconds since start().
  double elapsed(double now) const { return now - started_; }

 private:
  GoalWatchConfig config_;
  double started_ = 0.0, progress_time_ = 0.0;
  Eigen::Vector2d progress_point_ = Eigen::Vector2d::Zero();
};

}  // namespace jetbot_rl
