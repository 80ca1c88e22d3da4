#include "jetbot_rl/ros/env_diagnostics.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_msgs/KeyValue.h>
#include <ros/console.h>

#include <cstdio>

namespace jetbot_rl {
namespace {

diagnostic_msgs::KeyValue keyValue(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue kv;
  kv.key = key;
  kv.value = value;
  return kv;
}

}  // namespace

EnvDiagnostics::EnvDiagnostics(ros::NodeHandle& nh, const std::string& name,
                               const std::string& mode, int num_envs)
    : pub_(nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10)),
      name_(name),
      mode_(mode),
      num_envs_(num_envs),
      last_publish_(std::chrono::steady_clock::now()) {
  msg_.status.resize(1);
  msg_.status[0].name = name_;
  msg_.status[0].hardware_id = "jetbot_rl";
}

void EnvDiagnostics::countRejection(const std::string& reason) {
  ++rejections_;
  last_rejection_ = reason;
}

void EnvDiagnostics::countMalformed(const std::string& reason) {
  ++malformed_;
  last_malformed_ = reason;
  countRejection(reason);
}

void EnvDiagnostics::noteDivergences(const std::vector<Divergence>& divergences,
                                     std::uint64_t total) {
  diverged_ = total;
  if (!divergences.empty()) last_divergence_ = divergences.back().reason;
}

void EnvDiagnostics::publish() {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last_publish_).count();
  const double rate = seconds > 0.0 ? (steps_ - steps_at_publish_) / seconds : 0.0;
  char rate_text[32];
  std::snprintf(rate_text, sizeof(rate_text), "%.1f", rate);

  diagnostic_msgs::DiagnosticStatus& s = msg_.status[0];
  const bool new_rejections = rejections_ > rejections_at_publish_;
  const bool new_divergences = diverged_ > diverged_at_publish_;
  s.level = (new_rejections || new_divergences) ? diagnostic_msgs::DiagnosticStatus::WARN
                                                : diagnostic_msgs::DiagnosticStatus::OK;
  if (new_rejections && new_divergences) {
    s.message = "rejected messages and diverged envs since the last report";
  } else if (new_rejections) {
    s.message = "rejected messages since the last report";
  } else if (new_divergences) {
    s.message = "diverged envs reset since the last report";
  } else {
    s.message = "OK";
  }
  s.values.clear();
  s.values.push_back(keyValue("mode", mode_));
  s.values.push_back(keyValue("num_envs", std::to_string(num_envs_)));
  s.values.push_back(keyValue("current step", std::to_string(step_)));
  s.values.push_back(keyValue("steps applied", std::to_string(steps_)));
  s.values.push_back(keyValue("step rate (steps/s)", rate_text));
  s.values.push_back(keyValue("rejected messages", std::to_string(rejections_)));
  s.values.push_back(keyValue("last rejection reason", last_rejection_));
  s.values.push_back(keyValue("malformed messages", std::to_string(malformed_)));
  s.values.push_back(keyValue("last malformed reason", last_malformed_));
  s.values.push_back(keyValue("diverged envs reset", std::to_string(diverged_)));
  s.values.push_back(keyValue("last divergence reason", last_divergence_));
  msg_.header.stamp = ros::Time::now();
  pub_.publish(msg_);

  last_publish_ = now;
  steps_at_publish_ = steps_;
  rejections_at_publish_ = rejections_;
  diverged_at_publish_ = diverged_;
}

}  // namespace jetbot_rl
