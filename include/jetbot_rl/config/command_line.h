#pragma once
// Option values of the programs' command lines, checked as strictly as the nodes' parameters.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "jetbot_rl/config/former_names.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/robot/package_path.h"

namespace jetbot_rl {

/// `value` of `option` as a whole number in [minimum, maximum] into `out`; false (with `error`
/// naming the option and the value, `out` unchanged) otherwise.
inline bool parseWholeNumber(const std::string& option, const std::string& value, long long minimum,
                             long long maximum, long long& out, std::string& error) {
  char* end = nullptr;
  errno = 0;
  const long long number = std::strtoll(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || errno != 0 || number < minimum || number > maximum) {
    error = "invalid " + option + " = " + value + " (a whole number in [" +
            std::to_string(minimum) + ", " + std::to_string(maximum) + "])";
    return false;
  }
  out = number;
  return true;
}

/// The same for an int.
inline bool parseWholeNumber(const std::string& option, const std::string& value, int minimum,
                             int maximum, int& out, std::string& error) {
  long long number = 0;
  if (!parseWholeNumber(option, value, static_cast<long long>(minimum),
                        static_cast<long long>(maximum), number, error)) {
    return false;
  }
  out = static_cast<int>(number);
  return true;
}

/// Takes argv as `--option value` pairs: `take(option, value, error)` stores one and returns false
/// for an option it does not know (or with `error` set for a bad value). False with `error`
/// naming the option when one is unknown, bad or lacks its value.
inline bool parseOptions(
    int argc, char** argv,
    const std::function<bool(const std::string&, const std::string&, std::string&)>& take,
    std::string& error) {
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    for (const FormerName& former : formerNames()) {
      if (option == former.name) {
        error = option + " " + former.refusal();
        return false;
      }
    }
    if (i + 1 >= argc) {
      error = "option " + option + " needs a value";
      return false;
    }
    if (!take(option, argv[i + 1], error)) {
      if (error.empty()) error = "unknown option " + option;
      return false;
    }
    if (!error.empty()) return false;
  }
  return true;
}

/// The options of the programs that build a batch in this process (jetbot_rl_bench,
/// jetbot_rl_demo, jetbot_rl_evaluate): --num-envs N --steps S --threads T --urdf PATH and
/// --config YAML (repeatable: EnvSetup fields, the env node's parameter names, later files win).
struct EnvProgramOptions {
  int num_envs = 1024;
  int steps = 1000;
  int threads = 0;  ///< 0: all cores
  std::string urdf;
  std::vector<std::string> configs;
  std::string gazebo_world;  ///< --gazebo-world: world/gazebo_world over the files'.

  /// Stores `option` when it is one of these (true; `error` set for a bad value), else false.
  bool take(const std::string& option, const std::string& value, std::string& error) {
    if (option == "--urdf") {
      urdf = value;
    } else if (option == "--config") {
      configs.push_back(value);
    } else if (option == "--gazebo-world") {
      gazebo_world = value;
    } else if (option == "--num-envs") {
      parseWholeNumber(option, value, 1, 1000000, num_envs, error);
    } else if (option == "--steps") {
      parseWholeNumber(option, value, 1, 100000000, steps, error);
    } else if (option == "--threads") {
      parseWholeNumber(option, value, 0, 1024, threads, error);
    } else {
      return false;
    }
    return true;
  }
  /// "[--num-envs N] [--steps S] [--threads T] [--urdf PATH] [--config YAML ...] ..."
  static const char* usage() {
    return "[--num-envs N] [--steps S] [--threads T] [--urdf PATH] [--config YAML ...] "
           "[--gazebo-world PATH]";
  }
  /// The setup the options describe: the files' fields over the defaults, then num_envs and
  /// threads. ConfigError naming the file or field.
  EnvSetup setup() const {
    EnvSetup s;
    readEnvSetupFiles(configs, s);
    if (!gazebo_world.empty()) s.env.world.gazebo_world = gazebo_world;
    s.env.num_envs = num_envs;
    s.env.num_threads = threads;
    return s;
  }
  /// Parses argv into these options; false after printing "<program>: <error>" and the usage on
  /// stderr (the program then exits 2).
  bool parse(int argc, char** argv, const char* program) {
    std::string error;
    const auto take_one = [this](const std::string& option, const std::string& value,
                                 std::string& error) { return take(option, value, error); };
    if (parseOptions(argc, argv, take_one, error)) return true;
    std::fprintf(stderr, "%s: %s\nusage: %s %s\n", program, error.c_str(), program, usage());
    return false;
  }
  /// The batch: setup() on the robot of `urdf` (ConfigError, ModelError); its package:// meshes
  /// found through ROS_PACKAGE_PATH (packagePathResolver()).
  std::unique_ptr<BatchedEnv> makeEnv() const {
    return jetbot_rl::makeEnv(RobotModel::fromUrdfFile(urdf, packagePathResolver()), setup());
  }
  /// package:// URIs found through ROS_PACKAGE_PATH (findPackageUri()): the programs need no ROS
  /// to read a URDF with package:// meshes.
  static MeshResolver packagePathResolver() { return &findPackageUri; }
};

/// The options of the programs that play a checkpoint on a batch in this process
/// (jetbot_rl_evaluate, jetbot_rl_nav_benchmark): --checkpoint PATH (required) --episodes N --seed
/// S, and EnvProgramOptions'.
struct PolicyProgramOptions {
  EnvProgramOptions env;
  std::string checkpoint;
  long long seed = 1000;
  int episodes = 0;

  /// Stores `option` when it is one of these (true; `error` set for a bad value), else false.
  bool take(const std::string& option, const std::string& value, std::string& error) {
    if (option == "--checkpoint") {
      checkpoint = value;
    } else if (option == "--episodes") {
      parseWholeNumber(option, value, 0, 10000000, episodes, error);
    } else if (option == "--seed") {
      parseWholeNumber(option, value, 0, std::numeric_limits<long long>::max(), seed, error);
    } else {
      return env.take(option, value, error);
    }
    return true;
  }
  /// Parses argv with these options and the program's own (`take_own`, tried first); false after
  /// printing "<program>: <error>" and "usage: <program> --checkpoint PATH [--episodes N] [--seed
  /// S] <own_usage> <EnvProgramOptions::usage()>" on stderr (the program then exits 2).
  template <typename TakeOwn>
  bool parse(int argc, char** argv, const char* program, const char* own_usage,
             TakeOwn&& take_own) {
    std::string error;
    const auto take_one = [&](const std::string& option, const std::string& value,
                              std::string& error) {
      return take_own(option, value, error) || take(option, value, error);
    };
    if (parseOptions(argc, argv, take_one, error) && checkpoint.empty()) {
      error = "--checkpoint is required";
    }
    if (error.empty()) return true;
    std::fprintf(stderr, "%s: %s\nusage: %s --checkpoint PATH [--episodes N] [--seed S] %s %s\n",
                 program, error.c_str(), program, own_usage, EnvProgramOptions::usage());
    return false;
  }
};

}  // namespace jetbot_rl
