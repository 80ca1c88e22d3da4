#include "jetbot_rl/tasks/task_factory.h"

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

[[noreturn]] void wrongVariant(const TaskConfig& config, const char* choices) {
  throwInvalid("reward_variant", "'" + enumName(config.reward_variant) + "'",
               "the " + enumName(config.task) + " task takes " + choices);
}

}  // namespace

void checkFieldRules(const TaskConfig& config) {
  const RewardVariant v = config.reward_variant;
  const bool any = v == RewardVariant::kDefault;
  switch (config.task) {
    case TaskKind::kCommand:
      if (!any && v != RewardVariant::kExp && v != RewardVariant::kSum &&
          v != RewardVariant::kProduct) {
        wrongVariant(config, "exp, sum or product (or default)");
      }
      break;
    case TaskKind::kNavigation:
      if (!any && v != RewardVariant::kProgress && v != RewardVariant::kSparse) {
        wrongVariant(config, "progress or sparse (or default)");
      }
      break;
    case TaskKind::kRoadFollowing:
      if (!any && v != RewardVariant::kProgress) wrongVariant(config, "progress (or default)");
      break;
    case TaskKind::kVelocity:  // one reward: the variant is ignored
      break;
  }
}

std::unique_ptr<Task> makeTask(const TaskConfig& config) {
  validateConfig(config);
  switch (config.task) {
    case TaskKind::kCommand:
      return std::make_unique<CommandTask>(
          config.reward_variant == RewardVariant::kSum       ? CommandTask::Variant::kSum
          : config.reward_variant == RewardVariant::kProduct ? CommandTask::Variant::kProduct
                                                             : CommandTask::Variant::kExp);
    case TaskKind::kNavigation:
      return std::make_unique<NavigationTask>(config.navigation,
                                              config.reward_variant == RewardVariant::kSparse
                                                  ? NavigationTask::Variant::kSparse
                                                  : NavigationTask::Variant::kProgress);
    case TaskKind::kRoadFollowing:
      return std::make_unique<RoadFollowingTask>(config.road);
    case TaskKind::kVelocity:
      break;
  }
  return std::make_unique<VelocityTask>();
}

std::unique_ptr<TaskObserver> makeObserver(const std::string& task, int action_dim,
                                           const ObserverSpec& observer) {
  switch (parseEnum<TaskKind>("task", task)) {
    case TaskKind::kCommand:
      return std::make_unique<CommandObserver>();
    case TaskKind::kNavigation:
      return std::make_unique<NavigationObserver>(observer, action_dim);
    case TaskKind::kRoadFollowing:
      return std::make_unique<RoadObserver>(action_dim);
    case TaskKind::kVelocity:
      break;
  }
  return std::make_unique<VelocityObserver>();
}

}  // namespace jetbot_rl
