#pragma once

#include <string>
#include <vector>

#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/// The velocity task's observation: the body-frame COM velocity.
class VelocityObserver : public TaskObserver {
 public:
  std::vector<std::string> observationNames() const override {
    return {"lin_vel_b_x", "lin_vel_b_y", "lin_vel_b_z"};
  }
  void observe(const MeasuredState& state, float* obs) const override;
};

/// The seed task: observation is the body-frame COM velocity, reward its norm, never terminal.
class VelocityTask : public Task {
 public:
  std::string name() const override { return "velocity"; }
  const TaskObserver& observer() const override { return observer_; }
  void observe(int env, const RootState& state, float* obs) const override;
  float reward(int env, const RootState& state) const override;

 private:
  VelocityObserver observer_;
};

}  // namespace jetbot_rl
