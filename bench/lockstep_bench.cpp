#include "lockstep_bench.h"

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <ros/transport_hints.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>

#include "jetbot_rl/EnvSpec.h"
#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/Step.h"
#include "jetbot_rl/WheelTargets.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/inline_callback_queue.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/robot_description.h"

namespace jetbot_rl {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kTimeout = 30.0;  // [s] for the env node to answer at all
constexpr int kActionSets = 8;     // random target vectors, cycled (no per-step generation)

/// Answers every EnvStep with the next WheelTargets and records the round-trip times.
class RoundTripper {
 public:
  RoundTripper(ros::NodeHandle& nh, const std::string& env_ns, const LockstepBenchOptions& o,
               const EnvSpec& spec, std::uint64_t first_step)
      : total_(o.params.steps + std::max(10, o.params.steps / 10)),
        warmup_(total_ - o.params.steps),
        answer_inline_(o.answer_inline) {
    Rng rng(12345);
    for (int k = 0; k < kActionSets; ++k) {
      std::vector<float> set(static_cast<std::size_t>(spec.num_envs) * spec.action_dim);
      for (std::size_t i = 0; i < set.size(); ++i) {
        const std::size_t d = i % spec.action_dim;
        set[i] = spec.action_low[d] +
                 static_cast<float>(rng.uniform()) * (spec.action_high[d] - spec.action_low[d]);
      }
      actions_.push_back(std::move(set));
    }
    round_trips_us_.reserve(total_);
    targets_.step = first_step;
    pub_ = nh.advertise<WheelTargets>(env_ns + "/wheel_targets", 1);
    // Answered in roscpp's network thread, as a fast learner would (no spinner hand-off), or in
    // run()'s thread.
    ros::NodeHandle inline_nh(nh);
    if (answer_inline_) {
      inline_nh.setCallbackQueue(&queue_);
    } else {
      inline_nh.setCallbackQueue(&own_queue_);
    }
    sub_ = inline_nh.subscribe(env_ns + "/env_step", 1, &RoundTripper::onEnvStep, this,
                               ros::TransportHints().tcpNoDelay());
  }

  /// Waits for both connections (set-up only, polled), then runs every round trip.
  bool run() {
    const auto deadline = Clock::now() + std::chrono::duration<double>(kTimeout);
    while (pub_.getNumSubscribers() == 0 || sub_.getNumPublishers() == 0) {
      if (Clock::now() > deadline || !ros::ok()) return false;
      ros::WallDuration(0.01).sleep();
    }
    // Sent unlocked: in one process (nodelets) the whole chain of answers may run inside this
    // call, as nested callbacks of the queues, and take the lock itself.
    send();
    std::unique_lock<std::mutex> lock(queue_.mutex());
    auto last_progress = Clock::now();
    std::size_t seen = done_;
    while (ros::ok() && done_ < total_) {
      if (answer_inline_) {
        // Woken by each answer; the time-out only lets Ctrl-C and a silent env node end the run.
        progress_.wait_for(lock, std::chrono::milliseconds(100));
      } else {
        lock.unlock();
        own_queue_.callAvailable(ros::WallDuration(0.1));  // blocks until an answer arrives
        lock.lock();
      }
      if (done_ != seen) {
        seen = done_;
        last_progress = Clock::now();
      } else if (Clock::now() - last_progress > std::chrono::duration<double>(kTimeout)) {
        return false;  // the env node stopped answering
      }
    }
    return done_ == total_;
  }

  const std::vector<double>& roundTripsUs() const { return round_trips_us_; }
  double timedSeconds() const { return std::chrono::duration<double>(end_ - start_).count(); }
  /// EnvStep.step after the last round trip.
  std::uint64_t lastStep() const { return targets_.step; }

 private:
  void send() {
    const auto& set = actions_[targets_.step % kActionSets];
    targets_.velocities.assign(set.begin(), set.end());
    sent_ = Clock::now();
    pub_.publish(boost::make_shared<const WheelTargets>(targets_));  // shared in one process
  }

  void onEnvStep(const EnvStep::ConstPtr& msg) {
    if (msg->step != targets_.step + 1) return;  // not the answer to our targets
    const auto now = Clock::now();
    ++done_;
    if (done_ == warmup_) start_ = now;
    if (done_ > warmup_) {
      round_trips_us_.push_back(std::chrono::duration<double, std::micro>(now - sent_).count());
    }
    end_ = now;
    targets_.step = msg->step;
    if (done_ < total_) send();
    progress_.notify_one();
  }

  const std::size_t total_, warmup_;
  std::vector<std::vector<float>> actions_;
  std::vector<double> round_trips_us_;
  WheelTargets targets_;
  const bool answer_inline_;
  InlineCallbackQueue queue_;     // onEnvStep runs under its mutex
  ros::CallbackQueue own_queue_;  // answer_inline_ false: run() calls onEnvStep
  std::condition_variable progress_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
  Clock::time_point sent_, start_, end_;
  std::size_t done_ = 0;
};

double percentile(std::vector<double> sorted, double p) {
  std::sort(sorted.begin(), sorted.end());
  const std::size_t i =
      std::min(sorted.size() - 1, static_cast<std::size_t>(p / 100.0 * sorted.size()));
  return sorted[i];
}

/// Round trips through the ~step service (persistent connection): [us] each, after a warm-up.
std::vector<double> serviceRoundTrips(ros::NodeHandle& nh, const std::string& env_ns, int steps,
                                      const EnvSpec& spec, std::uint64_t step, double& seconds) {
  ros::ServiceClient client = nh.serviceClient<Step>(env_ns + "/step", /*persistent=*/true);
  Step call;
  call.request.actions.velocities.assign(static_cast<std::size_t>(spec.num_envs) * spec.action_dim,
                                         5.0f);
  std::vector<double> round_trips;
  round_trips.reserve(steps);
  const int warmup = std::max(10, steps / 10);
  Clock::time_point start;
  for (int i = 0; i < warmup + steps; ++i) {
    if (i == warmup) start = Clock::now();
    call.request.actions.step = step;
    const auto sent = Clock::now();
    if (!client.call(call) || !call.response.success) {
      throw ConfigError("~step call failed: " + call.response.message);
    }
    if (i >= warmup) {
      round_trips.push_back(std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
    }
    step = call.response.state.step;
  }
  seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return round_trips;
}

void printRoundTrips(const char* path, const std::vector<double>& rtt, double seconds) {
  std::printf("%s round_trip_us p50=%.1f p90=%.1f p99=%.1f max=%.1f  control_steps_per_s=%.0f\n",
              path, percentile(rtt, 50), percentile(rtt, 90), percentile(rtt, 99),
              percentile(rtt, 100), rtt.size() / seconds);
}

/// env steps per second of the core with the env node's own parameters, in this process.
double coreFigure(ros::NodeHandle& nh, const std::string& env_ns, int steps) {
  const std::unique_ptr<BatchedEnv> batch =
      makeEnv(loadRobotDescription(nh), readParams<EnvSetup>(ros::NodeHandle(env_ns)));
  BatchedEnv& env = *batch;
  std::vector<float> actions(static_cast<std::size_t>(env.numEnvs()) * env.actionDim());
  Rng rng(12345);
  for (auto& a : actions) a = static_cast<float>(40.0 * rng.uniform() - 20.0);
  for (int s = 0; s < std::max(10, steps / 10); ++s) env.step(actions);
  const auto start = Clock::now();
  for (int s = 0; s < steps; ++s) env.step(actions);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return static_cast<double>(steps) * env.numEnvs() / seconds;
}

}  // namespace

int runLockstepBench(ros::NodeHandle& nh, const LockstepBenchOptions& o) {
  const std::string env_ns = nh.resolveName(o.params.env_node);
  const int num_envs = o.params.num_envs, steps = o.params.steps;
  const auto spec =
      ros::topic::waitForMessage<EnvSpec>(env_ns + "/spec", nh, ros::Duration(kTimeout));
  if (!spec) {
    std::fprintf(stderr, "jetbot_rl_ros_bench: no %s/spec within %.0f s: is jetbot_env running?\n",
                 env_ns.c_str(), kTimeout);
    return 1;
  }
  if (static_cast<int>(spec->num_envs) != num_envs) {
    std::fprintf(stderr,
                 "jetbot_rl_ros_bench: the env node has %u envs, not num_envs %d: launch it "
                 "with num_envs:=%d\n",
                 spec->num_envs, num_envs, num_envs);
    return 1;
  }
  ros::ServiceClient reset = nh.serviceClient<Reset>(env_ns + "/reset");
  Reset call;
  call.request.seed = -1;
  if (!reset.waitForExistence(ros::Duration(kTimeout)) || !reset.call(call) ||
      !call.response.success) {
    std::fprintf(stderr, "jetbot_rl_ros_bench: %s/reset failed\n", env_ns.c_str());
    return 1;
  }

  std::vector<double> topic_round_trips;
  double seconds = 0.0;
  std::uint64_t step = 0;
  {  // scoped: its EnvStep subscription ends before the service phase
    RoundTripper tripper(nh, env_ns, o, *spec, call.response.state.step);
    if (!tripper.run()) {
      std::fprintf(stderr, "jetbot_rl_ros_bench: the env node stopped answering\n");
      return 1;
    }
    topic_round_trips = tripper.roundTripsUs();
    seconds = tripper.timedSeconds();
    step = tripper.lastStep();
  }
  const double ros_figure = static_cast<double>(steps) * num_envs / seconds;
  std::printf("jetbot_rl_ros_bench: %d envs, %d lockstep round trips per path\n", num_envs, steps);
  printRoundTrips("topic  ", topic_round_trips, seconds);
  try {
    double service_seconds = 0.0;
    const auto service = serviceRoundTrips(nh, env_ns, steps, *spec, step, service_seconds);
    printRoundTrips("service", service, service_seconds);
  } catch (const Error& e) {
    std::fprintf(stderr, "jetbot_rl_ros_bench: service path skipped: %s\n", e.what());
  }
  if (o.compare_core) {
    try {
      const double core = coreFigure(nh, env_ns, steps);
      std::printf("core_env_steps_per_s=%.0f (same parameters, in this process)\n", core);
      std::printf("ros_over_core=%.3f\n", ros_figure / core);
    } catch (const Error& e) {
      std::fprintf(stderr, "jetbot_rl_ros_bench: core comparison skipped: %s\n", e.what());
    }
  }
  std::printf("env_steps_per_s=%.0f\n", ros_figure);
  std::fflush(stdout);  // in a nodelet manager whose output is a file: now, not at its exit
  return 0;
}

}  // namespace jetbot_rl
