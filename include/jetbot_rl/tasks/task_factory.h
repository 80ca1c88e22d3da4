#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/tasks/command_task.h"
#include "jetbot_rl/tasks/navigation_task.h"
#include "jetbot_rl/tasks/observer_spec.h"
#include "jetbot_rl/tasks/road_following_task.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/task_observer.h"
#include "jetbot_rl/tasks/velocity_task.h"

namespace jetbot_rl {

/// The tasks makeTask() builds.
enum class TaskKind {
  kVelocity,       ///< VelocityTask: drive fast (the walkthrough's first part).
  kCommand,        ///< CommandTask: turn to a random command and drive along it.
  kNavigation,     ///< NavigationTask: reach a goal without hitting anything.
  kRoadFollowing,  ///< RoadFollowingTask: follow a track of floor tape with the camera.
};

inline const EnumNameList<TaskKind>& enumNames(TaskKind) {
  static const EnumNameList<TaskKind> names{{TaskKind::kVelocity, "velocity"},
                                            {TaskKind::kCommand, "command"},
                                            {TaskKind::kNavigation, "navigation"},
                                            {TaskKind::kRoadFollowing, "road_following"}};
  return names;
}

/// The reward variants of every task; each task takes its own (default: its first).
enum class RewardVariant { kDefault, kExp, kSum, kProduct, kProgress, kSparse };

inline const EnumNameList<RewardVariant>& enumNames(RewardVariant) {
  static const EnumNameList<RewardVariant> names{
      {RewardVariant::kDefault, "default"},   {RewardVariant::kExp, "exp"},
      {RewardVariant::kSum, "sum"},           {RewardVariant::kProduct, "product"},
      {RewardVariant::kProgress, "progress"}, {RewardVariant::kSparse, "sparse"}};
  return names;
}

/// Which task an env runs: the `task`, `reward_variant` and `nav/...` parameters.
struct TaskConfig {
  TaskKind task = TaskKind::kVelocity;
  /// The task's reward: command exp (default), sum or product; navigation progress (default) or
  /// sparse; the velocity task has one.
  RewardVariant reward_variant = RewardVariant::kDefault;
  NavigationConfig navigation;  ///< The navigation task's.
  TrackConfig road;             ///< The road following task's.
};

template <typename C, typename V>
IfConfig<C, TaskConfig> visitFields(C& c, V&& v) {
  v("task", c.task, AnyValue{},
    "RL task: velocity (observes the body-frame COM velocity, rewarded by its norm), command "
    "(turn to a random command and drive along it), navigation (reach a goal without "
    "collisions; needs a laser scanner) or road_following (follow a track of floor tape; needs "
    "a camera).");
  v("reward_variant", c.reward_variant, AnyValue{},
    "The task's reward: command: exp (v_x exp(dot), default), sum (v_x + dot) or product (v_x "
    "dot); navigation: progress (default) or sparse; default: the task's first.");
  visitFields(c.navigation, v);
  visitFields(c.road, v);
}

/// The reward variant fits the task: ConfigError naming reward_variant otherwise.
void checkFieldRules(const TaskConfig& config);

/// Builds the configured task (ConfigError for a reward variant it does not take).
std::unique_ptr<Task> makeTask(const TaskConfig& config);

/// The observer of task `task` with `action_dim` last actions and the observation contract
/// `observer` (the same code the simulated task observes with; BatchSpec's makeObserver() passes
/// a spec's). ConfigError naming `task` for an unknown one, or a navigation contract without its
/// beams or range.
std::unique_ptr<TaskObserver> makeObserver(const std::string& task, int action_dim,
                                           const ObserverSpec& observer);

}  // namespace jetbot_rl
