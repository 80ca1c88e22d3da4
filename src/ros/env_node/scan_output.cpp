#include "jetbot_rl/ros/env_node/scan_output.h"

#include <algorithm>

namespace jetbot_rl {

sensor_msgs::LaserScan scanFrame(const BatchedEnv& env, int env_index, const RobotNames& names) {
  const ScannerSpec* spec = env.scanner();
  sensor_msgs::LaserScan scan;
  if (!spec) return scan;
  scan.header.frame_id = names.frame(env_index, spec->link);
  scan.angle_min = static_cast<float>(spec->min_angle);
  scan.angle_max = static_cast<float>(spec->max_angle);
  scan.angle_increment = static_cast<float>(spec->angleIncrement());
  scan.time_increment = 0.0f;  // every beam of a scan at once
  scan.scan_time = static_cast<float>(spec->update_every * env.controlDt());
  scan.range_min = static_cast<float>(spec->range_min);
  scan.range_max = static_cast<float>(spec->range_max);
  scan.ranges.resize(spec->samples);
  return scan;
}

void updateScan(const BatchedEnv& env, int env_index, const ros::Time& stamp,
                sensor_msgs::LaserScan& scan) {
  const float* ranges = env.view(env_index).scan();
  if (!ranges) return;
  std::copy(ranges, ranges + scan.ranges.size(), scan.ranges.begin());
  scan.header.stamp = stamp;
}

ScanOutput::ScanOutput(ros::NodeHandle& nh, const BatchedEnv& env, int envs,
                       const RobotNames& names, CountedSubscriberQueues& queues) {
  if (!env.scanner()) return;
  const int n = std::clamp(envs, 0, env.numEnvs());
  due_.assign(n, 0);
  for (int e = 0; e < n; ++e) {
    pubs_.push_back(
        advertiseCounted<sensor_msgs::LaserScan>(nh, names.topic(e, "scan"), 10, queues));
    scans_.push_back(scanFrame(env, e, names));
  }
}

void ScanOutput::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool) {
  for (std::size_t e = 0; e < scans_.size(); ++e) {
    if (!env.view(static_cast<int>(e)).scanned()) continue;
    updateScan(env, static_cast<int>(e), msg->header.stamp, scans_[e]);
    due_[e] = 1;
  }
}

void ScanOutput::send() {
  for (std::size_t e = 0; e < scans_.size(); ++e) {
    if (!due_[e]) continue;
    pubs_[e].publish(scans_[e]);
    due_[e] = 0;
  }
}

}  // namespace jetbot_rl
