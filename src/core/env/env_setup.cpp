#include "jetbot_rl/env/env_setup.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/config/yaml_flatten.h"

namespace jetbot_rl {

std::unique_ptr<BatchedEnv> makeEnv(RobotModelConstPtr robot, const EnvSetup& setup) {
  validateConfig(setup);
  return std::make_unique<BatchedEnv>(std::move(robot), setup.env, makeTask(setup.task));
}

void readEnvSetupFiles(const std::vector<std::string>& paths, EnvSetup& setup) {
  for (const std::string& path : paths) {
    if (const std::string problem = fileProblem(path); !problem.empty()) {
      throw ConfigError("cannot read the parameter file " + path + ": it " + problem);
    }
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw ConfigError("cannot read the parameter file " + path);
    const std::string map_before = setup.env.world.map;
    const std::string gazebo_before = setup.env.world.gazebo_world;
    try {
      // Parsed as YAML (rosparam's reading): block lists, anchors, quoted values.
      fieldsFromYaml(flattenYaml(text.str()), setup);
    } catch (const ConfigError& e) {
      throw ConfigError(path + ": " + e.what());
    }
    // A map or world this file names by a relative path lies beside the file (as a map YAML's
    // image).
    for (auto [file, before] : {std::pair{&setup.env.world.map, &map_before},
                                std::pair{&setup.env.world.gazebo_world, &gazebo_before}}) {
      if (*file != *before && !file->empty() && std::filesystem::path(*file).is_relative()) {
        *file = (std::filesystem::path(path).parent_path() / *file).string();
      }
    }
  }
}

}  // namespace jetbot_rl
