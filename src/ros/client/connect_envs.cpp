#include "jetbot_rl/ros/client/connect_envs.h"

#include "jetbot_rl/Reset.h"
#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/ros/client/ros_vec_env.h"

namespace jetbot_rl {

// The Python client reads the stride from the service definition: both must agree.
static_assert(MultiVecEnv::kSeedStride == Reset::Request::NODE_SEED_STRIDE,
              "Reset.srv's NODE_SEED_STRIDE and MultiVecEnv::kSeedStride differ");

std::unique_ptr<VecEnv> connectEnvs(const std::vector<std::string>& names, bool lockstep,
                                    double timeout, const std::atomic<bool>* stop,
                                    const ros::NodeHandle& parent) {
  if (names.size() == 1) {
    return std::make_unique<RosVecEnv>(names[0], lockstep, timeout, stop, parent);
  }
  std::vector<std::unique_ptr<VecEnv>> parts;
  for (const std::string& name : names) {
    parts.push_back(std::make_unique<RosVecEnv>(name, lockstep, timeout, stop, parent));
  }
  return std::make_unique<MultiVecEnv>(std::move(parts), names);
}

}  // namespace jetbot_rl
