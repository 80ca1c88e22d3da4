#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/task.h"

namespace jetbot_rl {

/// Names accepted by makeTask().
std::vector<std::string> taskNames();

/// Builds task `name` ("velocity" or "command"); `reward` selects the command task's reward
/// variant ("exp", "sum", "product") and is ignored by the velocity task. Throws ConfigError
/// naming the parameter and value.
std::unique_ptr<Task> makeTask(const std::string& name, const std::string& reward = "exp");

}  // namespace jetbot_rl
