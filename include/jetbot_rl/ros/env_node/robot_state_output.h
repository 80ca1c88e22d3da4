#pragma once

#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/JointState.h>

#include <vector>

#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/ros/env_node/state_output.h"

namespace jetbot_rl {

/// Odometry covariance (pose and twist, diagonal): the odometry is the simulated state itself
/// (ground truth, as Gazebo's `odometrySource: world`), exact but for rounding; a small positive
/// variance keeps filters that invert it (robot_localization) well-posed [m^2, rad^2, (m/s)^2,
/// (rad/s)^2].
inline constexpr double kOdomVariance = 1e-9;

/// Odometry of env `env`, frames named by `names`: frame `<prefix>odom`, child frame
/// `<prefix><root link>`, covariances kOdomVariance (set once).
nav_msgs::Odometry odometryFrame(const BatchedEnv& env, int env_index, const RobotNames& names);
/// Sets `odom`'s stamp, the root link's pose in the env's frame and its twist in the root link
/// frame from `env`'s current state.
void updateOdometry(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                    nav_msgs::Odometry& odom);
/// Sets `state` (names and sizes from BatchedEnv::jointNames(), set once when empty) to env
/// `env_index`'s joint positions [rad], velocities [rad/s] and drive efforts [N m]; `scratch` is
/// reused, so nothing allocates after the first call.
void updateJointState(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                      JointStates& scratch, sensor_msgs::JointState& state);

/**
 * The robot view's state of envs 0..envs-1: `<prefix>odom` (nav_msgs/Odometry: frame
 * `<prefix>odom` at the env's origin, child frame `<prefix><root link>`, the root link's pose in
 * the env and its twist in the root link frame) and `<prefix>joint_states`
 * (sensor_msgs/JointState: every revolute and continuous joint's position, velocity and drive
 * effort), stamped with simulation time, at most `rate` Hz of simulation time and after every
 * reset (SimRateGate). Messages are allocated once and reused.
 */
class RobotStateOutput : public StateOutput {
 public:
  /// Topics relative to `nh` (the node's namespace), their queues kept in `queues`; `envs`
  /// clamped to the batch.
  RobotStateOutput(ros::NodeHandle& nh, const BatchedEnv& env, int envs, double rate,
                   const RobotNames& names, CountedSubscriberQueues& queues);
  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;

 private:
  SimRateGate gate_;
  bool due_ = false;
  std::vector<ros::Publisher> odom_pubs_, joint_pubs_;
  std::vector<nav_msgs::Odometry> odom_;
  std::vector<sensor_msgs::JointState> joints_;
  JointStates scratch_;
};

}  // namespace jetbot_rl
