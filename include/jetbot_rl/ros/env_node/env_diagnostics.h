#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/ros/env_node/env_server.h"

namespace jetbot_rl {

/// The env node's counters (EnvCounters), published as one DiagnosticStatus on /diagnostics.
class EnvDiagnostics {
 public:
  /// `name`: status name ("jetbot_env: environment"); `mode`: mode name shown as a value.
  EnvDiagnostics(ros::NodeHandle& nh, const std::string& name, const std::string& mode,
                 int num_envs);
  /// Publishes `counters` with the step rate [steps/s, wall] since the previous publish; WARN
  /// when rejections or divergences were added since then. `step`: the current EnvStep.step.
  void publish(const EnvCounters& counters, std::uint64_t step);

 private:
  ros::Publisher pub_;
  int num_envs_;
  EnvCounters previous_;
  std::chrono::steady_clock::time_point last_publish_;
  diagnostic_msgs::DiagnosticArray msg_;
};

}  // namespace jetbot_rl
