#pragma once

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "command_line.h"
#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/// Command line of the benchmark programs: --envs N --steps S --threads T --urdf PATH
/// --config PATH.
struct BenchArgs {
  int envs = 1024;
  int steps = 1000;
  int threads = 0;  ///< 0: all cores
  std::string urdf = JETBOT_RL_DEFAULT_URDF;
  std::string
      config;  ///< EnvConfig fields as YAML over the defaults (e.g. randomisation); "": none
};

/// Parses argv into `args`; false with `error` naming the bad option or value.
inline bool parseBenchArgs(int argc, char** argv, BenchArgs& args, std::string& error) {
  const auto take = [&args](const std::string& option, const std::string& value,
                            std::string& error) {
    if (option == "--urdf" || option == "--config") {
      (option == "--urdf" ? args.urdf : args.config) = value;
      return true;
    }
    int* target = option == "--envs"      ? &args.envs
                  : option == "--steps"   ? &args.steps
                  : option == "--threads" ? &args.threads
                                          : nullptr;
    if (!target) return false;
    parseWholeNumber(option, value, option == "--threads" ? 0 : 1, 100000000, *target, error);
    return true;
  };
  return parseOptions(argc, argv, take, error);
}

/// The batch the programs step: `args.envs` Jetbots from `args.urdf` on `args.threads` threads,
/// every other setting the seed's default or, with `args.config`, that file's (ConfigError when it
/// cannot be read).
inline std::unique_ptr<BatchedEnv> makeBenchEnv(const BenchArgs& args) {
  EnvConfig config;
  if (!args.config.empty()) {
    std::ifstream file(args.config);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw ConfigError("--config " + args.config + ": cannot be read");
    fieldsFromYaml(text.str(), config);
  }
  config.num_envs = args.envs;
  config.num_threads = args.threads;
  return std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(args.urdf), config);
}

}  // namespace jetbot_rl
