// jetbot_rl_dataset --out DIR [--kind collision_avoidance|road_following] [--count N] [--seed S]
// [--blocked-distance M] [--lookahead M] [--quality Q] [--config YAML ...] [--urdf PATH]
// [--num-envs N]: the Jetbot notebooks' data sets from simulated, randomised worlds
// (docs/dataset.md).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/dataset/notebook_dataset.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  EnvProgramOptions env_options;
  env_options.num_envs = 16;
  env_options.threads = 1;
  DatasetOptions options;
  std::string kind = "collision_avoidance";
  const auto number = [](const std::string& option, const std::string& value, double lo, double hi,
                         double& out, std::string& error) {
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !(x >= lo && x <= hi)) {
      error = "invalid " + option + " = " + value + " (a number in [" + std::to_string(lo) + ", " +
              std::to_string(hi) + "] m)";
      return;
    }
    out = x;
  };
  long long seed = 0;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--out") {
      options.out = value;
    } else if (option == "--kind") {
      kind = value;
    } else if (option == "--count") {
      parseWholeNumber(option, value, 2, 10000000, options.count, error);
    } else if (option == "--seed") {
      parseWholeNumber(option, value, 0LL, 1LL << 62, seed, error);
    } else if (option == "--quality") {
      parseWholeNumber(option, value, 1, 100, options.quality, error);
    } else if (option == "--blocked-distance") {
      number(option, value, 0.01, 100.0, options.blocked_distance, error);
    } else if (option == "--lookahead") {
      number(option, value, 0.01, 100.0, options.lookahead, error);
    } else {
      return env_options.take(option, value, error);
    }
    return true;
  };
  std::string error;
  if (parseOptions(argc, argv, take, error) && options.out.empty()) error = "--out is required";
  if (!error.empty()) {
    std::fprintf(stderr,
                 "jetbot_rl_dataset: %s\nusage: jetbot_rl_dataset --out DIR [--kind "
                 "collision_avoidance|road_following] [--count N] [--seed S] [--blocked-distance "
                 "M] [--lookahead M] [--quality Q] %s\n",
                 error.c_str(), EnvProgramOptions::usage());
    return 2;
  }
  try {
    options.kind = parseEnum<DatasetKind>("--kind", kind);
    options.seed = static_cast<std::uint64_t>(seed);
    if (env_options.urdf.empty()) env_options.urdf = JETBOT_RL_CAMERA_URDF;
    const std::unique_ptr<BatchedEnv> env = env_options.makeEnv();
    const DatasetSummary s = writeNotebookDataset(*env, options);
    std::printf("out=%s\nkind=%s\nblocked=%d\nfree=%d\nroad=%d\nresets=%d\n", options.out.c_str(),
                kind.c_str(), s.blocked, s.free, s.road, s.resets);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_dataset: %s\n", e.what());
    return 1;
  }
  return 0;
}
