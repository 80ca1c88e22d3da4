#include "jetbot_rl/tasks/velocity_task.h"

namespace jetbot_rl {

void VelocityObserver::observe(const MeasuredState& state, float* obs) const {
  const Eigen::Vector3d v = state.root.comLinearVelocityBody();
  obs[0] = static_cast<float>(v.x());
  obs[1] = static_cast<float>(v.y());
  obs[2] = static_cast<float>(v.z());
}

void VelocityTask::observe(int, const RootState& state, float* obs) const {
  MeasuredState measured;
  measured.root = state;
  observer_.observe(measured, obs);
}

float VelocityTask::reward(int, const RootState& state) const {
  return static_cast<float>(state.comLinearVelocityBody().norm());
}

}  // namespace jetbot_rl
