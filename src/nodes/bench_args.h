#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/// Command line of the benchmark programs: --envs N --steps S --threads T --urdf PATH.
struct BenchArgs {
  int envs = 1024;
  int steps = 1000;
  int threads = 0;  ///< 0: all cores
  std::string urdf = JETBOT_RL_DEFAULT_URDF;
};

/// Parses argv into `args`; false with `error` naming the bad option or value.
inline bool parseBenchArgs(int argc, char** argv, BenchArgs& args, std::string& error) {
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc) {
      error = "option " + option + " needs a value";
      return false;
    }
    const std::string value = argv[++i];
    if (option == "--urdf") {
      args.urdf = value;
      continue;
    }
    char* end = nullptr;
    const long number = std::strtol(value.c_str(), &end, 10);
    const bool valid = end && *end == '\0' && !value.empty();
    int* target = option == "--envs"      ? &args.envs
                  : option == "--steps"   ? &args.steps
                  : option == "--threads" ? &args.threads
                                          : nullptr;
    if (!target) {
      error = "unknown option " + option;
      return false;
    }
    const long minimum = option == "--threads" ? 0 : 1;
    if (!valid || number < minimum || number > 100000000) {
      error = "invalid " + option + " = " + value;
      return false;
    }
    *target = static_cast<int>(number);
  }
  return true;
}

/// The batch the programs step: `args.envs` Jetbots from `args.urdf` on `args.threads` threads,
/// every other setting the seed's default.
inline std::unique_ptr<BatchedEnv> makeBenchEnv(const BenchArgs& args) {
  EnvConfig config;
  config.num_envs = args.envs;
  config.num_threads = args.threads;
  return std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(args.urdf), config);
}

}  // namespace jetbot_rl
