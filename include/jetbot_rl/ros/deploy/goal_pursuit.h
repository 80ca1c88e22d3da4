#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/LaserScan.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/planning/goal_watch.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/ros/deploy/goal_input.h"
#include "jetbot_rl/ros/deploy/path_follower.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/**
 * A navigation goal from its acceptance to its end, as move_base pursues one with a learnt local
 * planner: goals from GoalInput (the move_base action and RViz's topic); with a map, a plan
 * (PathFollower) that a path policy observes and any other policy follows by a carrot (its goal
 * observation a point `carrot_distance` along the plan); a turn in place towards the way first
 * when it lies more than 1 rad off the robot's heading (a reactive policy may freeze on a goal
 * behind it), at each goal and after each recovery; arrival within `xy_goal_tolerance`,
 * then a turn in place to the goal's heading within `yaw_goal_tolerance`; recovery (back off,
 * re-plan around what the scan sees, retried up to `max_planning_retries` times, turn to the way)
 * when the robot makes no progress or a re-plan finds no way, ABORTED when recoveries run out,
 * the goal times out, the inputs stay stale for `controller_patience` or the goal's client
 * disconnects.
 */
class GoalPursuit {
 public:
  /// What the robot does this control step.
  enum class Mode {
    kStand,   ///< No goal: stop (quiet: the driver sends one zero Twist).
    kPolicy,  ///< The policy acts on the measured state (its goal and path filled in).
    kTwist,   ///< A fixed twist (turning to the heading, backing off).
  };

  /// `path_lookahead` [m]: the policy observes a path with it (0: it does not);
  /// `footprint_radius` [m] plans for the robot; `new_episode` is called when a goal starts
  /// (the policy's memory starts over) and `stop_now` when one is canceled.
  GoalPursuit(ros::NodeHandle& nh, ros::NodeHandle& pnh, const DeployParams& p,
              double path_lookahead, double footprint_radius, GoalInput::OdomFrame odom_frame,
              std::function<void()> new_episode, std::function<void()> stop_now);

  /// True when goals are planned on the map: a policy that observes a path
  /// (`path_lookahead` > 0 [m]), or any other with a map and a carrot.
  static bool plansPaths(const DeployParams& p, double path_lookahead) {
    return path_lookahead > 0.0 || (!p.map_topic.empty() && p.carrot_distance > 0.0);
  }
  /// One control step on fresh inputs: fills `state`'s goal (and path) for kPolicy, or `twist`.
  Mode step(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan,
            MeasuredState& state, PlanarTwist& twist);
  /// One control step on stale inputs (`what` names them): ABORTED after controller_patience.
  void stale(const std::string& what);
  /// True while a goal is pursued.
  bool active() const { return goals_.goal().has_value(); }
  /// What the driver's status tells: the goal topic, plans, re-plans and recoveries.
  std::string describe() const;
  void addStatus(const std::function<void(const std::string&, const std::string&)>& add) const;

 private:
  static double now();
  void end(const std::string& why);
  /// Plans for a new goal; false when it ended.
  bool planNewGoal(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan);
  /// A recovery for `why` (stuck, no path any more): backing off, or ABORTED after
  /// max_recoveries.
  Mode startRecovery(const std::string& why, const Eigen::Vector2d& p, double t,
                     PlanarTwist& twist);
  /// A recovery's step: backing off, then planning again (standing; retried), then turning.
  Mode recover(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan,
               const Eigen::Vector2d& p, double t, PlanarTwist& twist);

  DeployParams params_;
  double path_lookahead_, footprint_radius_;
  ros::Publisher footprint_pub_;  // the footprint planned for, once odometry names the frame
  bool footprint_sent_ = false;
  GoalInput goals_;
  std::unique_ptr<PathFollower> path_;  // with a map: a path policy or a carrot
  int path_map_ = 0;                    // the map the follower plans on
  bool new_goal_ = false;               // a goal came since the last step
  GoalWatch watch_;
  bool xy_reached_ = false;     // latched: only the heading is left
  bool aligning_ = false;       // checking the way's bearing first (a goal's start, a recovery)
  bool align_turning_ = false;  // ... and turning in place towards it
  bool align_fully_ = false;    // ... after a recovery: whenever it is off
  int recoveries_ = 0, recoveries_total_ = 0;
  std::optional<double> backing_off_since_;  // a recovery's back-off [s]
  Eigen::Vector2d backoff_from_ = Eigen::Vector2d::Zero();
  std::optional<double> plan_due_;     // a recovery plans again at this time [s]
  int planning_retries_ = 0;           // ... after this many failed plans
  std::optional<double> stale_since_;  // [s]
};

}  // namespace jetbot_rl
