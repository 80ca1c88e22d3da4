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

/// Which task an env runs: the `task` and `reward_variant` parameters.
struct TaskConfig {
  TaskKind task = TaskKind::kVelocity;
  /// The command task's reward; ignored by the velocity task.
  CommandTask::Variant reward_variant = CommandTask::Variant::kExp;
};

template <typename C, typename V>
IfConfig<C, TaskConfig> visitFields(C& c, V&& v) {
  v("task", c.task, AnyValue{},
    "RL task: velocity (observes the body-frame COM velocity, rewarded by its norm) or command "
    "(turn to a random command and drive along it).");
  v("reward_variant", c.reward_variant, AnyValue{},
    "Command task's reward: exp (v_x exp(dot)), sum (v_x + dot) or product (v_x dot).");
}

/// Builds the configured task.
std::unique_ptr<Task> makeTask(const TaskConfig& config);

}  // namespace jetbot_rl
