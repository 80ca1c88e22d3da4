#include "jetbot_rl/task_factory.h"

#include "jetbot_rl/command_task.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {

std::vector<std::string> taskNames() { return {"velocity", "command"}; }

std::unique_ptr<Task> makeTask(const std::string& name, const std::string& reward) {
  if (name == "velocity") return std::make_unique<VelocityTask>();
  if (name == "command") return std::make_unique<CommandTask>(CommandTask::parseVariant(reward));
  throw ConfigError("invalid task = '" + name + "': must be velocity or command");
}

}  // namespace jetbot_rl
