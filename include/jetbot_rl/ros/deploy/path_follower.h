#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/planning/map_planner.h"
#include "jetbot_rl/planning/path_tracker.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/// How the deploy node plans and follows a path (a policy trained with nav/path).
struct PathFollowing {
  MapPlannerConfig planner;       ///< The footprint and the training's clearances.
  double lookahead = 0.6;         ///< The observed point's distance along the path [m].
  double replan_distance = 0.5;   ///< Farther from the path re-plans [m].
  double blocked_distance = 1.0;  ///< The path this far ahead is checked against the scan [m].
  double replan_period = 1.0;     ///< At most one re-plan per this [s, wall].
};

/**
 * The global half of move_base's split on a robot, for a policy that follows a path: plans on
 * the map (MapPlanner, in the map's frame, around what the scan sees), publishes the plan as a
 * nav_msgs/Path on `~plan` (RViz shows it), tracks the robot along it through tf (map -> odom
 * looked up at each step, so a drifting localisation is followed) and re-plans when the robot
 * strays or a scan point the map does not hold lies on the path ahead within the footprint.
 * Gives the observer what the simulated task gives it: the goal, the path left and the
 * look-ahead point, in the odometry frame.
 */
class PathFollower {
 public:
  PathFollower(ros::NodeHandle& pnh, const PathFollowing& config, const tf2_ros::Buffer& tf);

  /// Takes `map` (its frame `frame`) to plan on; false with `why` when it has no room.
  bool setMap(const OccupancyMap& map, const std::string& frame, std::string& why);
  /// Plans to `goal` (the map's frame) from the robot of `odom`; "" or why not (an empty plan
  /// is published then). `scan`: what the scanner sees, or null.
  std::string plan(const Eigen::Vector2d& goal, const nav_msgs::Odometry& odom,
                   const sensor_msgs::LaserScan* scan);
  /// One control step along the plan: fills `state`'s goal, path_remaining and lookahead (odometry
  /// frame); re-plans when the robot strayed or the way is blocked. "" or why the goal must end
  /// (no transform, no path any more).
  std::string follow(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan,
                     MeasuredState& state);
  /// Drops the plan (an empty Path is published).
  void clear();
  /// True while a plan is followed (from plan() until clear()).
  bool following() const { return goal_.has_value(); }
  /// Plans made since start-up, and of them re-plans (strayed, blocked).
  int plans() const { return plans_; }
  int replans() const { return replans_; }
  /// The current plan's points (the map's frame).
  const std::vector<Eigen::Vector2d>& points() const { return tracker_.points(); }
  /// The plan in the odometry frame of the last follow() step, and its point `distance` [m] past
  /// the robot (the goal at its end), for a local planner that follows it; false without a plan.
  bool way(double distance, std::vector<Eigen::Vector2d>& points, Eigen::Vector2d& ahead) const;

 private:
  /// The scan's endpoints in the map's frame (none without a scan or its transform).
  std::vector<Eigen::Vector2d> seen(const sensor_msgs::LaserScan* scan) const;
  /// Why the path ahead is blocked by `points` ("" when it is not).
  std::string blocked(const std::vector<Eigen::Vector2d>& points) const;
  void publish(const std::vector<Eigen::Vector2d>& points);

  PathFollowing config_;
  const tf2_ros::Buffer& tf_;
  ros::Publisher plan_pub_;
  std::unique_ptr<MapPlanner> planner_;
  std::string map_frame_;
  std::optional<Eigen::Vector2d> goal_;  // the map's frame
  PathTracker tracker_;
  Eigen::Isometry2d odom_map_ = Eigen::Isometry2d::Identity();  // at the last follow() step
  ros::WallTime last_plan_;
  int plans_ = 0, replans_ = 0;
};

}  // namespace jetbot_rl
