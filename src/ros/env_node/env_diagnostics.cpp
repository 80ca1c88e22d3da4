#include "jetbot_rl/ros/env_node/env_diagnostics.h"

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
      num_envs_(num_envs),
      last_publish_(std::chrono::steady_clock::now()) {
  msg_.status.resize(1);
  msg_.status[0].name = name;
  msg_.status[0].hardware_id = "jetbot_rl";
  msg_.status[0].values = {keyValue("mode", mode)};
}

void EnvDiagnostics::publish(const EnvCounters& c, std::uint64_t step) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last_publish_).count();
  const double rate = seconds > 0.0 ? (c.steps - previous_.steps) / seconds : 0.0;
  char rate_text[32];
  std::snprintf(rate_text, sizeof(rate_text), "%.1f", rate);

  diagnostic_msgs::DiagnosticStatus& s = msg_.status[0];
  const bool new_rejections =
      c.rejections > previous_.rejections || c.cmd_vel_rejections > previous_.cmd_vel_rejections;
  const bool new_divergences = c.diverged > previous_.diverged;
  const bool new_timeouts = c.pacing_timeouts > previous_.pacing_timeouts;
  const bool new_undelivered = c.undelivered > previous_.undelivered;
  s.level = (new_rejections || new_divergences || new_timeouts || new_undelivered)
                ? diagnostic_msgs::DiagnosticStatus::WARN
                : diagnostic_msgs::DiagnosticStatus::OK;
  if (new_rejections && new_divergences) {
    s.message = "rejected messages and diverged envs since the last report";
  } else if (new_rejections) {
    s.message = "rejected messages since the last report";
  } else if (new_divergences) {
    s.message = "diverged envs reset since the last report";
  } else if (new_timeouts) {
    s.message = "published states that roscpp's network thread was too late for";
  } else if (new_undelivered) {
    s.message = "messages not delivered to subscribers that fell behind";
  } else {
    s.message = "OK";
  }
  s.values.resize(1);  // keeps "mode"
  s.values.push_back(keyValue("num_envs", std::to_string(num_envs_)));
  s.values.push_back(keyValue("current step", std::to_string(step)));
  s.values.push_back(keyValue("steps applied", std::to_string(c.steps)));
  s.values.push_back(keyValue("step rate (steps/s)", rate_text));
  s.values.push_back(keyValue("rejected messages", std::to_string(c.rejections)));
  s.values.push_back(keyValue("last rejection reason", c.last_rejection));
  s.values.push_back(keyValue("diverged envs reset", std::to_string(c.diverged)));
  s.values.push_back(keyValue("last divergence reason", c.last_divergence));
  s.values.push_back(keyValue("malformed messages", std::to_string(c.malformed)));
  s.values.push_back(keyValue("last malformed reason", c.last_malformed));
  s.values.push_back(keyValue("rejected cmd_vel", std::to_string(c.cmd_vel_rejections)));
  s.values.push_back(keyValue("last cmd_vel rejection reason", c.last_cmd_vel_rejection));
  s.values.push_back(keyValue("obstacles left out", std::to_string(c.obstacles_left_out)));
  s.values.push_back(keyValue("generated layouts unmade", std::to_string(c.layouts_unmade)));
  s.values.push_back(keyValue("movers left out", std::to_string(c.movers_left_out)));
  s.values.push_back(keyValue("states paced", std::to_string(c.paced_states)));
  s.values.push_back(keyValue("pacing time-outs", std::to_string(c.pacing_timeouts)));
  s.values.push_back(keyValue("env_step queue", std::to_string(c.env_step_queue)));
  s.values.push_back(keyValue("undelivered messages", std::to_string(c.undelivered)));
  s.values.push_back(keyValue("undelivered by topic", c.undelivered_by_topic));
  msg_.header.stamp = ros::Time::now();
  pub_.publish(msg_);
  last_publish_ = now;
  previous_ = c;
}

}  // namespace jetbot_rl
