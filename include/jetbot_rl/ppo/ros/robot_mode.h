#pragma once

#include <ros/node_handle.h>

#include <atomic>
#include <string>
#include <vector>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/env_config.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {
namespace ppo {

/// jetbot_policy_node's robot mode: odometry in, cmd_vel out, for a real robot's driver (or the
/// env node's robot view). Defaults suit the stock Jetbot's ROS 2 driver (dusty-nv/jetbot_ros).
/// The control rate, the action bounds and whether the actions are wheel targets or a twist come
/// from the checkpoint (the env it was trained on), not from parameters.
struct RobotModeParams {
  TaskConfig task;  ///< The task the policy was trained on (unset: the checkpoint's).
  std::string odom_topic = "odom";                ///< nav_msgs/Odometry of the robot.
  std::string cmd_vel_topic = "/jetbot/cmd_vel";  ///< geometry_msgs/Twist the driver takes.
  std::string command_topic = "~command";         ///< geometry_msgs/Vector3: command task's (x, y).
  double odom_timeout = 0.5;                      ///< Older odometry stops the robot [s, wall].
  /// Wheel radius [m] for wheel targets -> Twist: the driver's, which turns the Twist back into
  /// wheel speeds (stock Jetbot: 0.0603 m wheels); 0: from robot_description.
  double wheel_radius = 0.0603 / 2;
  /// Wheel separation [m], the driver's (stock Jetbot: 0.1016); 0: from robot_description.
  double wheel_separation = 0.1016;
  /// The wheel joints in the policy's action order (used with robot_description).
  std::vector<std::string> dof_names{"left_wheel_joint", "right_wheel_joint"};
  // ---- the navigation task (NavigationDriver) ----
  std::string scan_topic = "scan";                    ///< sensor_msgs/LaserScan of the robot.
  std::string goal_topic = "/move_base_simple/goal";  ///< geometry_msgs/PoseStamped (RViz).
  std::string outcome_topic = "~outcome";             ///< std_msgs/String: what became of a goal.
  double scan_timeout = 0.5;                          ///< An older scan stops the robot [s, wall].
  /// The policy's beams, [first, last] angle [rad] in the scanner's frame: empty, the
  /// checkpoint's; only a checkpoint that predates them needs it (nav/beams evenly spread).
  std::vector<double> scan_angles;
  /// The policy's [range_min, range_max] [m]: empty, the checkpoint's (likewise).
  std::vector<double> scan_range;
  std::string map_topic;  ///< nav_msgs/OccupancyGrid: goals off its free cells refused; "": none.
};

template <typename C, typename V>
IfConfig<C, RobotModeParams> visitFields(C& c, V&& v) {
  visitFields(c.task, v);
  v("odom_topic", c.odom_topic, AnyValue{}, "nav_msgs/Odometry of the robot.");
  v("cmd_vel_topic", c.cmd_vel_topic, AnyValue{}, "geometry_msgs/Twist the robot's driver takes.");
  v("command_topic", c.command_topic, AnyValue{},
    "geometry_msgs/Vector3: the command task's command (x, y).");
  v("odom_timeout", c.odom_timeout, positive("s, wall"), "Older odometry stops the robot.");
  v("wheel_radius", c.wheel_radius, atLeast(0.0, "m", "0: from robot_description"),
    "Wheel radius for wheel targets -> Twist: the driver's (stock Jetbot: 0.0603 m wheels).");
  v("wheel_separation", c.wheel_separation, atLeast(0.0, "m", "0: from robot_description"),
    "Wheel separation for wheel targets -> Twist: the driver's (stock Jetbot: 0.1016 m).");
  v("dof_names", c.dof_names, NameList{},
    "The two wheel joints in the policy's action order (used with robot_description).");
  v("scan_topic", c.scan_topic, AnyValue{}, "Navigation: the robot's sensor_msgs/LaserScan.");
  v("goal_topic", c.goal_topic, AnyValue{},
    "Navigation: geometry_msgs/PoseStamped goals (RViz's 2D Nav Goal), transformed into the "
    "odometry frame with tf2.");
  v("outcome_topic", c.outcome_topic, AnyValue{},
    "Navigation: std_msgs/String, what became of each goal (reached, refused: ...).");
  v("scan_timeout", c.scan_timeout, positive("s, wall"),
    "Navigation: an older scan stops the robot.");
  v("scan_angles", c.scan_angles,
    EachValue<double>{Range<double>{-10.0, 10.0, false, false, "rad"}},
    "Navigation: [first, last] angle in the scanner's frame of the beams the robot's scan is "
    "resampled to. Empty: the checkpoint's (given, it must agree with them); only a checkpoint "
    "written before checkpoints held their beams needs it, with nav/beams evenly spread.");
  v("scan_range", c.scan_range, EachValue<double>{Range<double>{0.0, 1000.0, false, false, "m"}},
    "Navigation: [range_min, range_max] readings are clamped into and divided by the max of. "
    "Empty: the checkpoint's (likewise).");
  v("map_topic", c.map_topic, AnyValue{"", "empty: none"},
    "Navigation: nav_msgs/OccupancyGrid in the odometry frame; a goal off its free cells is "
    "refused.");
}

/// dof_names must name two wheel joints; scan_angles and scan_range none or two values.
void checkFieldRules(const RobotModeParams& params);

/// How the checkpoint's policy runs: at 1 / its control step, with its action bounds, its actions
/// wheel targets or a twist (v, omega). ConfigError naming the file for a checkpoint without its
/// env's spec (format 1).
struct PolicyRun {
  double control_rate = 0.0;  ///< [Hz]
  bool twist = false;         ///< Actions (linear_x, angular_z) rather than wheel targets.
  std::vector<double> action_high;
  std::string checkpoint;  ///< Its file, for messages.
};
PolicyRun policyRunOf(const Policy& policy, const std::string& checkpoint);

/// Runs the robot mode until `stop` or ROS shutdown: reads the parameters above under `pnh`,
/// then at the policy's control rate turns the newest odometry into the task's observation, acts
/// with the policy's mean and publishes its action as a Twist. The policy's memory starts over
/// when it starts driving: at start-up, at a new command (goal) and after a stop for stale input.
/// Returns the exit code.
int runRobotMode(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy,
                 const std::string& checkpoint, const std::atomic<bool>& stop);

}  // namespace ppo
}  // namespace jetbot_rl
