#include "jetbot_rl/env/local_vec_env.h"

namespace jetbot_rl {

LocalVecEnv::LocalVecEnv(std::unique_ptr<BatchedEnv> env)
    : env_(std::move(env)), spec_(env_->spec()) {}

const StepResult& LocalVecEnv::reset(std::int64_t seed,
                                     const std::vector<std::uint32_t>& episode_steps) {
  std::optional<std::uint64_t> reseed;
  if (seed >= 0) reseed = static_cast<std::uint64_t>(seed);
  stepped_ = false;
  return env_->reset({}, reseed, episode_steps);
}

void LocalVecEnv::stepAsync(const std::vector<float>& actions) {
  if (stepped_) throw Error("LocalVecEnv: stepAsync() twice without stepWait()");
  env_->step(actions);
  stepped_ = true;
}

const StepResult& LocalVecEnv::stepWait() {
  if (!stepped_) throw Error("LocalVecEnv: stepWait() without stepAsync()");
  stepped_ = false;
  return env_->state();
}

}  // namespace jetbot_rl
