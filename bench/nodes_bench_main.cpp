// jetbot_rl_nodes_bench --env-nodes A[,B...] --steps S: lockstep env steps per second through one
// or several running jetbot_env nodes stepped as one batch (MultiVecEnv), random targets.
#include <ros/ros.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/ros/client/connect_envs.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "jetbot_rl_nodes_bench", ros::init_options::AnonymousName);
  std::vector<std::string> nodes;
  int steps = 1000;
  std::string error;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--env-nodes") {
      std::istringstream list(value);
      for (std::string name; std::getline(list, name, ',');) nodes.push_back(name);
    } else if (option == "--steps") {
      jetbot_rl::parseWholeNumber(option, value, 1, 100000000, steps, error);
    } else {
      return false;
    }
    return true;
  };
  if (jetbot_rl::parseOptions(argc, argv, take, error) && nodes.empty()) {
    error = "--env-nodes is required";
  }
  if (!error.empty()) {
    std::fprintf(
        stderr,
        "jetbot_rl_nodes_bench: %s\nusage: jetbot_rl_nodes_bench --env-nodes A[,B...] --steps S\n",
        error.c_str());
    return 2;
  }
  try {
    const auto env = jetbot_rl::connectEnvs(nodes, /*lockstep=*/true, 30.0, nullptr);
    const int n = env->spec().num_envs, a = env->spec().action_dim;
    std::mt19937 gen(1);
    std::uniform_real_distribution<float> target(-20.0f, 20.0f);
    std::vector<float> actions(static_cast<std::size_t>(n) * a);
    for (auto& x : actions) x = target(gen);
    env->reset(0);
    for (int s = 0; s < std::max(1, steps / 10); ++s) env->step(actions);  // warm-up
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
      if (s % 50 == 0)
        for (auto& x : actions) x = target(gen);  // new targets every 50 steps
      env->step(actions);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("nodes=%zu envs=%d steps=%d wall_s=%.3f\n", nodes.size(), n, steps, seconds);
    std::printf("env_steps_per_s=%.0f\n", static_cast<double>(steps) * n / seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_nodes_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
