#pragma once

#include <ros/node_handle.h>

#include <atomic>
#include <string>
#include <vector>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {
namespace ppo {

/// jetbot_policy_node's robot mode: odometry in, cmd_vel out, for a real robot's driver (or the
/// env node's robot view). Defaults suit the stock Jetbot's ROS 2 driver (dusty-nv/jetbot_ros).
struct RobotModeParams {
  TaskConfig task;                                ///< The task the policy was trained on.
  std::string odom_topic = "odom";                ///< nav_msgs/Odometry of the robot.
  std::string cmd_vel_topic = "/jetbot/cmd_vel";  ///< geometry_msgs/Twist the driver takes.
  std::string command_topic = "~command";         ///< geometry_msgs/Vector3: command task's (x, y).
  double control_rate = 60.0;  ///< Policy steps per second [Hz] (1 / control_dt).
  double odom_timeout = 0.5;   ///< Older odometry stops the robot [s, wall].
  /// Wheel radius [m] for wheel targets -> Twist: the driver's, which turns the Twist back into
  /// wheel speeds (stock Jetbot: 0.0603 m wheels); 0: from robot_description.
  double wheel_radius = 0.0603 / 2;
  /// Wheel separation [m], the driver's (stock Jetbot: 0.1016); 0: from robot_description.
  double wheel_separation = 0.1016;
  /// The wheel joints in the policy's action order (used with robot_description).
  std::vector<std::string> dof_names{"left_wheel_joint", "right_wheel_joint"};
  /// The wheel velocity limit the policy was trained with [rad/s]: its actions span +-this.
  double wheel_velocity_limit = 20.0;
};

template <typename C, typename V>
IfConfig<C, RobotModeParams> visitFields(C& c, V&& v) {
  visitFields(c.task, v);
  v("odom_topic", c.odom_topic, AnyValue{}, "nav_msgs/Odometry of the robot.");
  v("cmd_vel_topic", c.cmd_vel_topic, AnyValue{}, "geometry_msgs/Twist the robot's driver takes.");
  v("command_topic", c.command_topic, AnyValue{},
    "geometry_msgs/Vector3: the command task's command (x, y).");
  v("control_rate", c.control_rate, positiveUpTo(10000.0, "Hz"),
    "Policy steps per second (1 / the control step the policy was trained with).");
  v("odom_timeout", c.odom_timeout, positive("s, wall"), "Older odometry stops the robot.");
  v("wheel_radius", c.wheel_radius, atLeast(0.0, "m", "0: from robot_description"),
    "Wheel radius for wheel targets -> Twist: the driver's (stock Jetbot: 0.0603 m wheels).");
  v("wheel_separation", c.wheel_separation, atLeast(0.0, "m", "0: from robot_description"),
    "Wheel separation for wheel targets -> Twist: the driver's (stock Jetbot: 0.1016 m).");
  v("dof_names", c.dof_names, NameList{},
    "The two wheel joints in the policy's action order (used with robot_description).");
  v("wheel_velocity_limit", c.wheel_velocity_limit, positive("rad/s"),
    "The wheel velocity limit the policy was trained with: its actions span +-this.");
}

/// dof_names must name two wheel joints.
void checkFieldRules(const RobotModeParams& params);

/// Runs the robot mode until `stop` or ROS shutdown: reads the parameters above under `pnh`,
/// then at control_rate turns the newest odometry into the task's observation, acts with the
/// policy's mean and publishes the wheel targets as a Twist. Returns the exit code.
int runRobotMode(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy,
                 const std::atomic<bool>& stop);

}  // namespace ppo
}  // namespace jetbot_rl
