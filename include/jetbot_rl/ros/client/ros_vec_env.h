#pragma once

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_client.h>
#include <ros/subscriber.h>

#include <atomic>
#include <functional>
#include <string>

#include "jetbot_rl/EnvSpec.h"
#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/WheelTargets.h"
#include "jetbot_rl/env/vec_env.h"
#include "jetbot_rl/ros/common/drop_counter.h"

namespace jetbot_rl {

/**
 * A jetbot_env node as a VecEnv, through its public interface only: waits for the latched
 * `<env>/spec`, calls `<env>/reset`, publishes `<env>/wheel_targets` (tcpNoDelay) and waits for
 * the matching `<env>/env_step`.
 *
 * Lockstep: stepAsync() publishes targets with `step` = the current EnvStep.step; stepWait()
 * blocks until the EnvStep with step + 1 arrives (resending the targets every 0.5 s without an
 * answer: a message sent while the env's subscription is still connecting is lost; a late
 * duplicate is rejected by the env as stale). Realtime: stepWait() blocks until any newer EnvStep
 * arrives (the node steps on its own clock). Every wait blocks on a private callback queue (no
 * polling sleeps), up to `timeout`, and ends early with Interrupted when `*stop` becomes true.
 */
class RosVecEnv : public VecEnv {
 public:
  /// Connects to the env node `env_ns` (e.g. /jetbot_env; a relative name resolves in
  /// `parent`'s namespace) and waits for its spec; throws Error after `timeout` [s] or
  /// Interrupted.
  RosVecEnv(const std::string& env_ns, bool lockstep, double timeout, const std::atomic<bool>* stop,
            const ros::NodeHandle& parent = ros::NodeHandle());

  const BatchSpec& spec() const override { return spec_; }
  /// Calls ~reset (all envs, `seed` >= 0 reseeds, `episode_steps` staggered starts) and waits
  /// until its published state arrives on ~env_step (proving the subscription is connected);
  /// calls it again once a second until then. Error naming the node when the call fails, is
  /// refused or gets no answer within `timeout`; Interrupted when stopped meanwhile.
  const StepResult& reset(std::int64_t seed,
                          const std::vector<std::uint32_t>& episode_steps = {}) override;
  /// Publishes `actions` [rad/s] (num_envs x action_dim) for the current step.
  void stepAsync(const std::vector<float>& actions) override;
  /// Waits for the answer to stepAsync(): Error naming the node after `timeout`.
  const StepResult& stepWait() override;

  /// Called for every EnvStep received after the last reset (realtime mode may deliver several
  /// per step; they all pass here, in order).
  void setObserver(std::function<void(const EnvStep&)> observer) {
    observer_ = std::move(observer);
  }
  /// The node's name, resolved (e.g. /jetbot_env).
  const std::string& name() const { return env_ns_; }
  /// Messages refused unread so far (array or string lengths exceeding their bytes), also
  /// counted on /diagnostics as "<this node>: env client <env>".
  std::uint64_t refusedMessages() const { return refused_.count(); }

 private:
  void onSpec(const EnvSpec::ConstPtr& msg);
  void onEnvStep(const EnvStep::ConstPtr& msg);
  /// ~reset with `srv`, waiting at most `timeout`; throws as reset() says.
  void callReset(Reset& srv);
  /// Processes callbacks until `done()` (true) or `timeout` [s] (false); Interrupted when
  /// stopped.
  bool waitUntil(const std::function<bool()>& done, double timeout, const std::string& what);
  /// Processes callbacks until `done()` or the deadline: Error(`what`) after `timeout`.
  void waitFor(const std::function<bool()>& done, double timeout, const std::string& what);

  std::string env_ns_;
  bool lockstep_;
  double timeout_;
  const std::atomic<bool>* stop_;
  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;
  ros::Subscriber spec_sub_, step_sub_;
  ros::Publisher targets_pub_;
  ros::ServiceClient reset_client_;

  bool has_spec_ = false;
  std::string spec_error_;  ///< Why a received EnvSpec was refused.
  BatchSpec spec_;
  StepResult result_;
  WheelTargets::Ptr targets_;   ///< A new message per step: in-process subscribers share it.
  bool sent_ = false;           ///< stepAsync() awaits its stepWait().
  std::uint64_t step_ = 0;      ///< EnvStep.step of result_.
  bool accepting_ = false;      ///< After a reset: EnvSteps newer than step_ are taken.
  bool connected_ = false;      ///< An EnvStep has been received: the subscription works.
  std::uint64_t observed_ = 0;  ///< Newest step passed to the observer.
  EnvStep::ConstPtr newest_;    ///< Newest EnvStep with step > step_.
  std::function<void(const EnvStep&)> observer_;
  DropCounter refused_;
};

}  // namespace jetbot_rl
