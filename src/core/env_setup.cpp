#include "jetbot_rl/env_setup.h"

#include <fstream>
#include <sstream>

namespace jetbot_rl {

std::unique_ptr<BatchedEnv> makeEnv(RobotModelConstPtr robot, const EnvSetup& setup) {
  validateConfig(setup);
  return std::make_unique<BatchedEnv>(std::move(robot), setup.env, makeTask(setup.task));
}

void readEnvSetupFiles(const std::vector<std::string>& paths, EnvSetup& setup) {
  for (const std::string& path : paths) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw ConfigError("cannot read the parameter file " + path);
    try {
      fieldsFromYaml(text.str(), setup);
    } catch (const ConfigError& e) {
      throw ConfigError(path + ": " + e.what());
    }
  }
}

}  // namespace jetbot_rl
