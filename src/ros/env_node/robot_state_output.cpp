#include "jetbot_rl/ros/env_node/robot_state_output.h"

#include <algorithm>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/env_node/queue_size.h"

namespace jetbot_rl {
namespace {

// A slow subscriber loses old states, never slows stepping.

void setDiagonal(boost::array<double, 36>& covariance) {
  covariance.fill(0.0);
  for (int i = 0; i < 6; ++i) covariance[7 * i] = kOdomVariance;
}

void toMsg(const Eigen::Vector3d& v, geometry_msgs::Vector3& m) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

}  // namespace

nav_msgs::Odometry odometryFrame(const BatchedEnv& env, int env_index, const RobotNames& names) {
  nav_msgs::Odometry odom;
  odom.header.frame_id = names.frame(env_index, kOdomFrame);
  odom.child_frame_id = names.frame(env_index, env.robot().bodies().front().link_name);
  setDiagonal(odom.pose.covariance);
  setDiagonal(odom.twist.covariance);
  return odom;
}

void updateOdometry(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                    nav_msgs::Odometry& odom) {
  odom.header.stamp = stamp;
  const RootState root = env.view(env_index).rootState();  // in the env's frame: odom's
  setPose(odom.pose.pose, root.position, root.orientation);
  const BodyTwist twist =
      env.view(env_index).rootTwist();  // in the root link frame: child_frame_id's
  toMsg(twist.linear, odom.twist.twist.linear);
  toMsg(twist.angular, odom.twist.twist.angular);
}

void updateJointState(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                      JointStates& scratch, sensor_msgs::JointState& state) {
  if (state.name.empty()) state.name = env.jointNames();
  state.header.stamp = stamp;
  env.view(env_index).jointStates(scratch);
  // assign() of equal sizes reuses the capacity
  state.position.assign(scratch.position.begin(), scratch.position.end());
  state.velocity.assign(scratch.velocity.begin(), scratch.velocity.end());
  state.effort.assign(scratch.effort.begin(), scratch.effort.end());
}

RobotStateOutput::RobotStateOutput(ros::NodeHandle& nh, const BatchedEnv& env, int envs,
                                   double rate, const RobotNames& names,
                                   CountedSubscriberQueues& queues)
    : gate_(rate) {
  const int n = std::clamp(envs, 0, env.numEnvs());
  for (int e = 0; e < n; ++e) {
    odom_pubs_.push_back(advertiseCounted<nav_msgs::Odometry>(nh, names.topic(e, "odom"),
                                                              kEnvNodeQueueSize, queues));
    joint_pubs_.push_back(advertiseCounted<sensor_msgs::JointState>(
        nh, names.topic(e, "joint_states"), kEnvNodeQueueSize, queues));
    odom_.push_back(odometryFrame(env, e, names));
    joints_.emplace_back();
  }
}

void RobotStateOutput::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) {
  if (odom_.empty() || !gate_.due(msg->header.stamp, reset)) return;
  for (std::size_t e = 0; e < odom_.size(); ++e) {
    updateOdometry(env, static_cast<int>(e), msg->header.stamp, odom_[e]);
    updateJointState(env, static_cast<int>(e), msg->header.stamp, scratch_, joints_[e]);
  }
  due_ = true;
}

void RobotStateOutput::send() {
  if (!due_) return;
  due_ = false;
  for (std::size_t e = 0; e < odom_.size(); ++e) {
    odom_pubs_[e].publish(odom_[e]);
    joint_pubs_[e].publish(joints_[e]);
  }
}

}  // namespace jetbot_rl
