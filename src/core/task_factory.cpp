#include "jetbot_rl/task_factory.h"

namespace jetbot_rl {

std::unique_ptr<Task> makeTask(const TaskConfig& config) {
  switch (config.task) {
    case TaskKind::kCommand:
      return std::make_unique<CommandTask>(config.reward_variant);
    case TaskKind::kVelocity:
      break;
  }
  return std::make_unique<VelocityTask>();
}

}  // namespace jetbot_rl
