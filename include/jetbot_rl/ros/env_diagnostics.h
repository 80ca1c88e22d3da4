#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/// Counters of the environment node, published as one DiagnosticStatus on /diagnostics.
class EnvDiagnostics {
 public:
  /// `name`: status name ("jetbot_env: environment"); `mode`: mode name shown as a value.
  EnvDiagnostics(ros::NodeHandle& nh, const std::string& name, const std::string& mode,
                 int num_envs);
  /// Counts one applied control step; `step` is the EnvStep.step after it.
  void countStep(std::uint64_t step) {
    ++steps_;
    step_ = step;
  }
  /// Counts one rejected WheelTargets message or ~step call.
  void countRejection(const std::string& reason);
  /// Counts one message or service request refused unread (its lengths exceed its bytes); it is
  /// also a rejection.
  void countMalformed(const std::string& reason);
  /// Records envs reset because they diverged; `total` is BatchedEnv::divergedCount().
  void noteDivergences(const std::vector<Divergence>& divergences, std::uint64_t total);
  /// Publishes the status with the step rate [steps/s, wall] since the previous publish.
  void publish();
  /// Rejected messages so far.
  std::uint64_t rejections() const { return rejections_; }
  /// Messages and requests refused unread so far.
  std::uint64_t malformed() const { return malformed_; }

 private:
  ros::Publisher pub_;
  std::string name_, mode_;
  int num_envs_;
  std::uint64_t step_ = 0, steps_ = 0, steps_at_publish_ = 0;
  std::uint64_t rejections_ = 0, rejections_at_publish_ = 0;
  std::uint64_t diverged_ = 0, diverged_at_publish_ = 0;
  std::uint64_t malformed_ = 0;
  std::string last_rejection_, last_divergence_, last_malformed_;
  std::chrono::steady_clock::time_point last_publish_;
  diagnostic_msgs::DiagnosticArray msg_;
};

}  // namespace jetbot_rl
