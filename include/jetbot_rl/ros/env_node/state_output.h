#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/time.h>

#include <cstdint>

#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/ros/common/counted_subscriber_queues.h"

namespace jetbot_rl {

/**
 * One thing the env node publishes about each new state (EnvStep, /clock, tf, markers, ...).
 * capture() runs under the node's state lock and copies what it needs; send() runs after the
 * lock is released (publishing, which serialises for every subscriber, holds up no step), in
 * the order the states were captured.
 */
class StateOutput {
 public:
  virtual ~StateOutput() = default;
  /// Takes what it will publish about `env`'s state, whose EnvStep is `msg` (stamped with
  /// simulation time); `reset`: the state comes from a ~reset (start-up included).
  virtual void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) = 0;
  /// Publishes what the last capture() took, if anything.
  virtual void send() = 0;
  /// Publishes what the node's end needs (e.g. DELETEALL markers); called once, before the
  /// node's publications are flushed and ROS shuts down.
  virtual void finish() {}
};

/// ~env_step: every state, as the EnvStep message itself (shared, never copied).
class EnvStepOutput : public StateOutput {
 public:
  /// `queue_size`: per subscriber connection [messages] (envStepQueueSize()), kept in `queues`.
  EnvStepOutput(ros::NodeHandle& pnh, std::uint32_t queue_size, CountedSubscriberQueues& queues);
  void capture(const BatchedEnv&, const EnvStep::ConstPtr& msg, bool) override { msg_ = msg; }
  void send() override;

 private:
  ros::Publisher pub_;
  EnvStep::ConstPtr msg_;
};

/// Decides when a rate-limited output sends: at most `rate` Hz of simulation time, at once after
/// a reset, but never twice with the same stamp (tf2 listeners drop repeated stamps: a reset's
/// batch at an unchanged time goes out with the next step instead).
class SimRateGate {
 public:
  explicit SimRateGate(double rate) : period_(1.0 / rate) {}
  /// True when a batch stamped `stamp` is due.
  bool due(const ros::Time& stamp, bool reset);

 private:
  ros::Duration period_;
  ros::Time last_{0, 0};
  bool sent_ = false;
  bool pending_ = false;  // a reset's batch waits for a new stamp
};

}  // namespace jetbot_rl
