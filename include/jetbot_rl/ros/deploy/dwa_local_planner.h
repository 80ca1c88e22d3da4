#pragma once

#include <sensor_msgs/LaserScan.h>

#include <Eigen/Core>
#include <vector>

#include "jetbot_rl/planning/dwa_planner.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/**
 * The classical baseline on a robot (`local_planner: dwa`): the DwaPlanner the navigation
 * benchmark's `dwa` rows drive with, on the robot's odometry, its scan's returns and the way to
 * the goal, in the odometry frame, where the policy would act (GoalPursuit's turns, arrival and
 * recoveries stay the same). The scan's beams start at the robot's position along its heading, as
 * the policy reads them (resampleScan()).
 */
class DwaLocalPlanner {
 public:
  /// `footprint_radius` [m] (plus dwa/footprint_padding): a trajectory that comes this near a
  /// return is refused.
  DwaLocalPlanner(const DwaConfig& config, double footprint_radius);

  /// One control step: the robot of `state` (its root, odometry frame), the returns of `scan`,
  /// and the way to the goal: `path` (the plan in the odometry frame; its point
  /// local_goal_distance past the robot, `local_goal`) or, `path` empty, the straight line to
  /// `state.goal`. The twist to command [m/s, rad/s].
  PlanarTwist step(const MeasuredState& state, const sensor_msgs::LaserScan& scan,
                   const std::vector<Eigen::Vector2d>& path, const Eigen::Vector2d& local_goal);
  /// Steps in which no trajectory was clear (a turn in place was commanded instead).
  long blockedSteps() const { return blocked_; }
  const DwaConfig& config() const { return planner_.config(); }

 private:
  DwaPlanner planner_;
  DwaInput in_;  // reused: its obstacles' storage
  long blocked_ = 0;
};

}  // namespace jetbot_rl
