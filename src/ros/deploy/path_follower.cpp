#include "jetbot_rl/ros/deploy/path_follower.h"

#include <nav_msgs/Path.h>
#include <ros/console.h>

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/deploy/planar_transform.h"

namespace jetbot_rl {

PathFollower::PathFollower(ros::NodeHandle& pnh, const PathFollowing& config,
                           const tf2_ros::Buffer& tf)
    : config_(config), tf_(tf) {
  plan_pub_ = pnh.advertise<nav_msgs::Path>("plan", 1, true);
}

bool PathFollower::setMap(const OccupancyMap& map, const std::string& frame, std::string& why) {
  try {
    planner_ = std::make_unique<MapPlanner>(map, config_.planner);
  } catch (const ConfigError& e) {
    planner_.reset();
    why = e.what();
    return false;
  }
  map_frame_ = frame;
  return true;
}

std::vector<Eigen::Vector2d> PathFollower::seen(const sensor_msgs::LaserScan* scan) const {
  std::vector<Eigen::Vector2d> points;
  Eigen::Isometry2d map_scan;
  std::string why;
  if (!scan || !lookupPlanar(tf_, map_frame_, scan->header.frame_id, map_scan, why)) return points;
  for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
    const float r = scan->ranges[i];
    if (!(r >= scan->range_min && r < scan->range_max)) continue;  // NaN and ±inf too
    const double a = scan->angle_min + static_cast<double>(i) * scan->angle_increment;
    points.push_back(map_scan * Eigen::Vector2d(r * std::cos(a), r * std::sin(a)));
  }
  return points;
}

std::string PathFollower::plan(const Eigen::Vector2d& goal, const nav_msgs::Odometry& odom,
                               const sensor_msgs::LaserScan* scan) {
  goal_.reset();
  if (!planner_) {
    publish({});
    return "no map to plan on yet";
  }
  Eigen::Isometry2d map_odom;
  std::string why;
  if (!lookupPlanar(tf_, map_frame_, odom.header.frame_id, map_odom, why)) {
    publish({});
    return why;
  }
  const auto& p = odom.pose.pose.position;
  const Eigen::Vector2d robot = map_odom * Eigen::Vector2d(p.x, p.y);
  std::vector<Eigen::Vector2d> path;
  why = planner_->plan(robot, goal, seen(scan), path);
  last_plan_ = ros::WallTime::now();
  publish(path);
  if (!why.empty()) return why;
  ++plans_;
  goal_ = goal;
  tracker_.reset(std::move(path));
  return "";
}

std::string PathFollower::blocked(const std::vector<Eigen::Vector2d>& points) const {
  const double radius = planner_->robotRadius();
  std::vector<Eigen::Vector2d> ahead;
  for (double s = 0.0; s <= config_.blocked_distance; s += 0.05) {
    ahead.push_back(tracker_.lookahead(s));
  }
  for (const Eigen::Vector2d& q : points) {
    if (planner_->explainedByMap(q)) continue;
    for (const Eigen::Vector2d& a : ahead) {
      if ((q - a).norm() < radius) {
        return "blocked at (" + std::to_string(q.x()) + ", " + std::to_string(q.y()) + ")";
      }
    }
  }
  return "";
}

std::string PathFollower::follow(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan,
                                 MeasuredState& state) {
  if (!goal_) return "no plan";
  Eigen::Isometry2d map_odom;
  std::string why;
  if (!lookupPlanar(tf_, map_frame_, odom.header.frame_id, map_odom, why)) return why;
  const auto& p = odom.pose.pose.position;
  const Eigen::Vector2d robot = map_odom * Eigen::Vector2d(p.x, p.y);
  tracker_.track(robot);
  std::string replan;
  if (ros::WallTime::now() - last_plan_ >= ros::WallDuration(config_.replan_period)) {
    if (tracker_.offset(robot) > config_.replan_distance) {
      replan = "strayed " + std::to_string(tracker_.offset(robot)) + " m from the path";
    } else if (config_.blocked_distance > 0.0) {
      replan = blocked(seen(scan));
    }
  }
  if (!replan.empty()) {
    ROS_INFO("re-planning: %s", replan.c_str());
    const Eigen::Vector2d goal = *goal_;
    why = plan(goal, odom, scan);
    if (!why.empty()) return why;
    ++replans_;
    tracker_.track(robot);
  }
  odom_map_ = map_odom.inverse();
  state.goal = odom_map_ * *goal_;
  state.path_remaining = tracker_.remaining(robot);
  state.lookahead = odom_map_ * tracker_.lookahead(config_.lookahead);
  return "";
}

bool PathFollower::way(double distance, std::vector<Eigen::Vector2d>& points,
                       Eigen::Vector2d& ahead) const {
  if (!goal_) return false;
  points.clear();
  for (const Eigen::Vector2d& p : tracker_.points()) points.push_back(odom_map_ * p);
  ahead = odom_map_ * tracker_.lookahead(distance);
  return true;
}

void PathFollower::clear() {
  goal_.reset();
  publish({});
}

void PathFollower::publish(const std::vector<Eigen::Vector2d>& points) {
  nav_msgs::Path path;
  path.header.frame_id = map_frame_;
  path.header.stamp = ros::Time::now();
  for (std::size_t i = 0; i < points.size(); ++i) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position.x = points[i].x();
    pose.pose.position.y = points[i].y();
    // Each waypoint faces the next; the goal faces along the last leg.
    const std::size_t from = i + 1 < points.size() ? i : (i > 0 ? i - 1 : i);
    const Eigen::Vector2d d = points[std::min(from + 1, points.size() - 1)] - points[from];
    const double yaw = std::atan2(d.y(), d.x());
    pose.pose.orientation.z = std::sin(0.5 * yaw);
    pose.pose.orientation.w = std::cos(0.5 * yaw);
    path.poses.push_back(pose);
  }
  plan_pub_.publish(path);
}

}  // namespace jetbot_rl
