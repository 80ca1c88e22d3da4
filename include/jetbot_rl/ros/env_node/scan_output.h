#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/LaserScan.h>

#include <vector>

#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/ros/env_node/state_output.h"

namespace jetbot_rl {

/// The LaserScan of env `env_index`'s scanner (its link's frame under `names`, angles, range,
/// scan time; ranges sized), empty without a scanner.
sensor_msgs::LaserScan scanFrame(const BatchedEnv& env, int env_index, const RobotNames& names);
/// Sets `scan`'s stamp and ranges (REP 117 values) from env `env_index`'s latest scan.
void updateScan(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                sensor_msgs::LaserScan& scan);

/**
 * `env_<i>/scan` (sensor_msgs/LaserScan) of the robot envs, at the scanner's rate: a message
 * after each step in which an env took a new scan, in the scanner link's frame, stamped with
 * simulation time; +inf beyond range_max and -inf below range_min (REP 117). Nothing without a
 * scanner.
 */
class ScanOutput : public StateOutput {
 public:
  /// Topics relative to `nh` (the node's namespace); `envs` clamped to the batch.
  ScanOutput(ros::NodeHandle& nh, const BatchedEnv& env, int envs, const RobotNames& names,
             CountedSubscriberQueues& queues);
  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;

 private:
  std::vector<ros::Publisher> pubs_;
  std::vector<sensor_msgs::LaserScan> scans_;
  std::vector<std::uint8_t> due_;  // per env
};

}  // namespace jetbot_rl
