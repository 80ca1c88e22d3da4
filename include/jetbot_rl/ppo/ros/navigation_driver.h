#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/diff_drive.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ros/robot_mode.h"
#include "jetbot_rl/ros/common/drop_counter.h"

namespace jetbot_rl {
namespace ppo {

/// Resamples a LaserScan to the policy's beams: nearest sample to each beam angle (a scan over a
/// full turn wraps), NaN and +inf as range_max, -inf as range_min, clamped into [range_min,
/// range_max] and divided by range_max. An empty result and `error` naming the angles when a
/// beam lies outside what the scan covers.
std::vector<float> resampleScan(const sensor_msgs::LaserScan& scan,
                                const std::vector<double>& beam_angles, double range_min,
                                double range_max, std::string& error);

/// The scan beams a navigation policy observes.
struct ScanBeams {
  std::vector<double> angles;  ///< In the scanner's frame, in observation order [rad].
  double range_min = 0.0;      ///< Readings are clamped into [range_min, range_max] [m]...
  double range_max = 0.0;      ///< ... and divided by range_max [m].
};

/// The beams of the policy trained on `trained` (its checkpoint's env spec); `scan_angles` and
/// `scan_range`, when given, must agree with them. A checkpoint written before it held its beams
/// takes them from those two parameters (nav/beams evenly spread), which it then needs.
/// ConfigError naming the parameter and both values.
ScanBeams scanBeamsOf(const BatchSpec& trained, const RobotModeParams& p,
                      const std::string& checkpoint);

/**
 * The robot mode of a navigation policy: the newest odometry, laser scan and goal (a PoseStamped
 * as RViz's "2D Nav Goal" publishes it, transformed into the odometry frame with tf2) become the
 * navigation task's observation; the policy's action is published as a Twist at the policy's
 * control rate (its memory starts over with each goal and after each stop).
 * The robot stays stopped without a goal, stops on arrival (goal_radius, outcome "reached") and
 * while the scan or the odometry are stale; a goal that is not finite, cannot be transformed or
 * lies off the map's free cells is refused with a warning and an outcome naming it.
 */
class NavigationDriver {
 public:
  NavigationDriver(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy,
                   const RobotModeParams& p, const PolicyRun& run,
                   const std::optional<DiffDrive>& kinematics);
  /// Stops ticking and leaves the robot standing (a zero Twist, written out).
  void stop();

 private:
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg);
  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg);
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void onTick(const ros::WallTimerEvent&);
  void report(const std::string& outcome);
  /// True when `goal` (odometry frame) lies on a free cell of the map, or no map is given.
  bool onFreeCell(const Eigen::Vector2d& goal, std::string& why) const;

  RobotModeParams params_;
  Policy& policy_;
  PolicyRun run_;
  std::optional<DiffDrive> kinematics_;  // wheel targets -> Twist; none for twist actions
  ScanBeams beams_of_policy_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Publisher cmd_vel_pub_, outcome_pub_;
  ros::Subscriber odom_sub_, scan_sub_, goal_sub_, map_sub_;
  ros::WallTimer timer_;
  nav_msgs::Odometry::ConstPtr odom_;
  sensor_msgs::LaserScan::ConstPtr scan_;
  nav_msgs::OccupancyGrid::ConstPtr map_;
  std::chrono::steady_clock::time_point odom_time_, scan_time_;
  std::optional<Eigen::Vector2d> goal_;  // in the odometry frame
  std::vector<float> beams_, obs_, actions_, last_action_;
  std::string scan_error_;  // the scan does not cover the policy's beams
  DropCounter dropped_;
};

}  // namespace ppo
}  // namespace jetbot_rl
