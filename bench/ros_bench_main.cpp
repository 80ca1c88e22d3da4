// jetbot_rl_ros_bench [--env-node NAME] --num-envs N --steps S: lockstep round trips against a
// running jetbot_env node (default /jetbot_env).
#include <ros/ros.h>

#include <cstdio>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "lockstep_bench.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  ros::init(argc, argv, "jetbot_rl_ros_bench", ros::init_options::AnonymousName);
  LockstepBenchOptions options;
  LockstepBenchParams& p = options.params;
  std::string error;
  // The env node's own parameters set its threads, robot and config: only these apply here.
  const auto take = [&p](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--env-node") {
      p.env_node = value;
    } else if (option == "--num-envs") {
      parseWholeNumber(option, value, 1, 1000000, p.num_envs, error);
    } else if (option == "--steps") {
      parseWholeNumber(option, value, 1, 100000000, p.steps, error);
    } else {
      return false;
    }
    return true;
  };
  if (!parseOptions(argc, argv, take, error)) {
    std::fprintf(stderr,
                 "jetbot_rl_ros_bench: %s\nusage: jetbot_rl_ros_bench [--env-node NAME] "
                 "[--num-envs N] [--steps S]\n",
                 error.c_str());
    return 2;
  }
  ros::NodeHandle nh;
  return runLockstepBench(nh, options);
}
