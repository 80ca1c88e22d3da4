#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/command_task.h"
#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/task.h"

namespace jetbot_rl {

/// The tasks makeTask() builds.
enum class TaskKind {
  kVelocity,  ///< VelocityTask: drive fast (the walkthrough's first part).
  kCommand,   ///< CommandTask: turn to a random command and drive along it.
};

inline const EnumNameList<TaskKind>& enumNames(TaskKind) {
  static const EnumNameList<TaskKind> names{{TaskKind::kVelocity, "velocity"},
                                            {TaskKind::kCommand, "command"}};
  return names;
}

/// Which task an env runs: the `task` and `reward` parameters.
struct TaskConfig {
  TaskKind task = TaskKind::kVelocity;
  CommandTask::Variant reward = CommandTask::Variant::kExp;  ///< Ignored by the velocity task.
};

template <typename C, typename V>
IfConfig<C, TaskConfig> visitFields(C& c, V&& v) {
  v("task", c.task, AnyValue{});
  v("reward", c.reward, AnyValue{});
}

/// Builds the configured task.
std::unique_ptr<Task> makeTask(const TaskConfig& config);

}  // namespace jetbot_rl
