#pragma once

#include <cstdint>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// Thrown by a VecEnv when asked to stop (e.g. Ctrl-C) while waiting.
class Interrupted : public Error {
 public:
  using Error::Error;
};

/**
 * A batch of envs with same-step auto-reset, as a learner sees it: in-process (LocalVecEnv) or
 * through a jetbot_env node (RosVecEnv). Stepping is split into send and wait, so that a learner
 * can keep several batches in flight (SB3's step_async / step_wait).
 */
class VecEnv {
 public:
  virtual ~VecEnv() = default;
  virtual const BatchSpec& spec() const = 0;
  /// Resets every env (`seed` >= 0 reseeds their random streams). `episode_steps`: empty, or
  /// num_envs episode steps to start at (< max_episode_length - 1; staggered starts, as rsl_rl's
  /// random initial episode lengths).
  virtual const StepResult& reset(std::int64_t seed,
                                  const std::vector<std::uint32_t>& episode_steps = {}) = 0;
  /// Sends num_envs x action_dim actions [env units] for one control step.
  virtual void stepAsync(const std::vector<float>& actions) = 0;
  /// Waits for the batch after the step sent by stepAsync().
  virtual const StepResult& stepWait() = 0;
  /// stepAsync() then stepWait().
  const StepResult& step(const std::vector<float>& actions) {
    stepAsync(actions);
    return stepWait();
  }
};

}  // namespace jetbot_rl
