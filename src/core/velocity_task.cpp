#include "jetbot_rl/task.h"

namespace jetbot_rl {

void VelocityTask::observe(int, const RootState& state, float* obs) const {
  const Eigen::Vector3d v = state.comLinearVelocityBody();
  obs[0] = static_cast<float>(v.x());
  obs[1] = static_cast<float>(v.y());
  obs[2] = static_cast<float>(v.z());
}

float VelocityTask::reward(int, const RootState& state) const {
  return static_cast<float>(state.comLinearVelocityBody().norm());
}

}  // namespace jetbot_rl
