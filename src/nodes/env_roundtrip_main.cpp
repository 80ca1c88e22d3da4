// jetbot_env_roundtrip: measures lockstep round trips against a running jetbot_env node, through
// the topics (WheelTargets out, EnvStep back) and through the ~step service.
//   rosrun jetbot_rl jetbot_env_roundtrip [steps] [node]     (defaults: 5000 /jetbot_env)
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "jetbot_rl/EnvStep.h"
#include "jetbot_rl/Reset.h"
#include "jetbot_rl/Step.h"
#include "jetbot_rl/WheelTargets.h"

namespace {

struct Figures {
  double steps_per_s;
  double us_per_step;
};

void print(const char* path, int num_envs, int steps, const Figures& f) {
  std::printf("%-8s N=%-5d %6d steps: %9.0f steps/s  %8.1f us/step\n", path, num_envs, steps,
              f.steps_per_s, f.us_per_step);
}

Figures figures(std::chrono::steady_clock::time_point start, int steps) {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {steps / s, 1e6 * s / steps};
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_env_roundtrip", ros::init_options::AnonymousName);
  const int steps = argc > 1 ? std::atoi(argv[1]) : 5000;
  const std::string node = argc > 2 ? argv[2] : "/jetbot_env";
  if (steps < 1) {
    std::fprintf(stderr, "usage: jetbot_env_roundtrip [steps >= 1] [node]\n");
    return 2;
  }
  ros::NodeHandle nh;
  ros::CallbackQueue queue;  // EnvStep callbacks, served by this thread only
  ros::NodeHandle qnh;
  qnh.setCallbackQueue(&queue);

  if (!ros::service::waitForService(node + "/reset", ros::Duration(30.0))) {
    std::fprintf(stderr, "no %s/reset service\n", node.c_str());
    return 1;
  }
  jetbot_rl::Reset reset;
  if (!ros::service::call(node + "/reset", reset) || !reset.response.success) {
    std::fprintf(stderr, "reset failed\n");
    return 1;
  }
  const int num_envs = static_cast<int>(reset.response.state.num_envs);
  std::uint64_t step = reset.response.state.step;

  std::uint64_t last = step;
  ros::Subscriber sub = qnh.subscribe<jetbot_rl::EnvStep>(
      node + "/env_step", 4, [&last](const jetbot_rl::EnvStep::ConstPtr& m) { last = m->step; },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  ros::Publisher pub = nh.advertise<jetbot_rl::WheelTargets>(node + "/wheel_targets", 4);
  const auto connect_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while ((pub.getNumSubscribers() == 0 || sub.getNumPublishers() == 0) &&
         std::chrono::steady_clock::now() < connect_deadline) {
    queue.callAvailable(ros::WallDuration(0.01));
  }
  queue.callAvailable(ros::WallDuration(0.2));  // drain anything published before

  jetbot_rl::WheelTargets targets;
  targets.velocities.assign(2 * num_envs, 5.0f);
  // --- topics ---
  const int warmup = std::min(200, steps);
  auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < warmup + steps; ++i) {
    if (i == warmup) start = std::chrono::steady_clock::now();
    targets.step = step;
    pub.publish(targets);
    while (last <= step && ros::ok()) queue.callAvailable(ros::WallDuration(1.0));
    if (last != step + 1) {
      std::fprintf(stderr, "expected EnvStep %llu, got %llu\n",
                   static_cast<unsigned long long>(step + 1),
                   static_cast<unsigned long long>(last));
      return 1;
    }
    step = last;
  }
  print("topic", num_envs, steps, figures(start, steps));

  // --- service (persistent connection); the node still publishes each EnvStep, to no one ---
  sub.shutdown();
  ros::ServiceClient client = nh.serviceClient<jetbot_rl::Step>(node + "/step", true);
  jetbot_rl::Step srv;
  srv.request.actions = targets;
  for (int i = 0; i < warmup + steps; ++i) {
    if (i == warmup) start = std::chrono::steady_clock::now();
    srv.request.actions.step = step;
    if (!client.call(srv) || !srv.response.success) {
      std::fprintf(stderr, "step call failed: %s\n", srv.response.message.c_str());
      return 1;
    }
    step = srv.response.state.step;
  }
  print("service", num_envs, steps, figures(start, steps));
  return 0;
}
