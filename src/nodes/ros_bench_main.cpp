// jetbot_rl_ros_bench --envs N --steps S: lockstep round trips against the running /jetbot_env.
#include <ros/ros.h>

#include <cstdio>
#include <string>

#include "bench_args.h"
#include "lockstep_bench.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_rl_ros_bench", ros::init_options::AnonymousName);
  jetbot_rl::BenchArgs args;
  std::string error;
  // The env node's own parameters set its threads, robot and config: only these two apply here.
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    if (option != "--envs" && option != "--steps") error = "unknown option " + option;
  }
  if (!error.empty() || !jetbot_rl::parseBenchArgs(argc, argv, args, error)) {
    std::fprintf(stderr, "jetbot_rl_ros_bench: %s\nusage: jetbot_rl_ros_bench --envs N --steps S\n",
                 error.c_str());
    return 2;
  }
  ros::NodeHandle nh;
  jetbot_rl::LockstepBenchOptions options;
  options.envs = args.envs;
  options.steps = args.steps;
  return jetbot_rl::runLockstepBench(nh, options);
}
