// jetbot_rl_world_map WORLD OUT.yaml [--resolution R] [--cut-height H]: a Gazebo world's grid, cut
// at H [m] (default: kDefaultCutHeight, 0.1, as a world without a scanner) with cells of R [m]
// (default 0.05), written as map_server's YAML + PGM: the map the env node serves on /map for
// world/gazebo_world, for map_server, AMCL or move_base.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/world_model.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  if (argc < 3 || argv[1][0] == '-' || argv[2][0] == '-') {
    std::fprintf(stderr,
                 "usage: jetbot_rl_world_map WORLD OUT.yaml [--resolution R] [--cut-height H]\n");
    return 2;
  }
  WorldConfig config;
  config.gazebo_world = argv[1];  // cut_height 0: resolveCutHeight()'s default
  std::string error;
  const auto take = [&](const std::string& option, const std::string& value, std::string& why) {
    double* out = option == "--resolution"   ? &config.map_resolution
                  : option == "--cut-height" ? &config.cut_height
                                             : nullptr;
    if (!out) return false;
    char* end = nullptr;
    *out = std::strtod(value.c_str(), &end);  // its range: checked as world/... below
    if (value.empty() || *end != '\0') why = "invalid " + option + " = " + value + " (a number)";
    return true;
  };
  if (!parseOptions(argc - 2, argv + 2, take, error)) {
    std::fprintf(stderr, "jetbot_rl_world_map: %s\n", error.c_str());
    return 2;
  }
  try {
    config.draws = false;    // no start: the spawn point need not be free to write the map
    validateConfig(config);  // the program's options are the boundary: WorldModel takes it as valid
    const WorldModel world(config, 0.0);
    for (const std::string& w : world.gazebo()->warnings) {
      std::fprintf(stderr, "jetbot_rl_world_map: warning: %s\n", w.c_str());
    }
    writeMapYaml(*world.map(), argv[2]);
    std::printf("%s: %d x %d cells of %g m, origin (%g, %g), cut at %g m\n", argv[2],
                world.map()->width, world.map()->height, world.map()->resolution,
                world.map()->origin_x, world.map()->origin_y, world.cutHeight());
  } catch (const Error& e) {
    std::fprintf(stderr, "jetbot_rl_world_map: %s\n", e.what());
    return 1;
  }
  return 0;
}
