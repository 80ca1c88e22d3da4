#pragma once

#include <memory>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/vec_env.h"

namespace jetbot_rl {

/// A BatchedEnv in the learner's own process, as a VecEnv: no ROS, no copies.
class LocalVecEnv : public VecEnv {
 public:
  explicit LocalVecEnv(std::unique_ptr<BatchedEnv> env);

  const BatchSpec& spec() const override { return spec_; }
  const StepResult& reset(std::int64_t seed,
                          const std::vector<std::uint32_t>& episode_steps = {}) override;
  /// Steps at once; InputError (nothing stepped) for a wrong size or a non-finite action.
  void stepAsync(const std::vector<float>& actions) override;
  const StepResult& stepWait() override;

  BatchedEnv& env() { return *env_; }

 private:
  std::unique_ptr<BatchedEnv> env_;
  BatchSpec spec_;
  bool stepped_ = false;  // a stepAsync() awaits its stepWait()
};

}  // namespace jetbot_rl
