#include "jetbot_rl/tasks/task.h"

#include <limits>

#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

std::vector<std::string> Task::observationNames() const { return observer().observationNames(); }

void TaskObserver::observationBounds(std::vector<float>& low, std::vector<float>& high) const {
  const std::size_t n = observationNames().size();
  low.assign(n, -std::numeric_limits<float>::infinity());
  high.assign(n, std::numeric_limits<float>::infinity());
}

}  // namespace jetbot_rl
