// Several robots in one world (robots_per_env, robot_team.h): how BatchedEnv steps the robots
// of one env, and starts their rounds.
#include <algorithm>

#include "env/env_physics.h"
#include "jetbot_rl/env/batched_env.h"
#include "scene/env_scene.h"
#include "scene/robot_team.h"
#include "sensors/camera_sensor.h"
#include "sensors/env_sensor.h"

namespace jetbot_rl {

void BatchedEnv::stepTeam(int group, WorkerContext& context) {
  RobotTeam& team = *scene_->team();
  const int first = team.firstRow(group), k = team.robotsPerEnv();
  // Every robot's physics from where the others were when the step began (captured at the end
  // of the last step, at a reset and by setRootState()), then every scan where they all are
  // after it; a robot that starts anew is seen there from the next step.
  // A robot waiting for its round to end (rounds) stands still, unseen by the others.
  const auto active = [&team](int e) { return !team.waiting(e); };
  scene_->beginWorldStep(group);
  for (int e = first; e < first + k; ++e) {
    if (active(e)) stepPhysics(e, context);
  }
  for (int e = first; e < first + k; ++e) {
    if (active(e)) team.capture(e, *envs_[e]);
  }
  for (int e = first; e < first + k; ++e) {
    if (active(e)) sensePhysics(e);
  }
  for (int e = first; e < first + k; ++e) {
    if (active(e)) {
      finishStep(e);
    } else {
      holdRow(e);
    }
  }
  if (config_.team.rounds && team.roundOver(group)) startRound(group);
}

void BatchedEnv::holdRow(int env) {
  result_.rewards[env] = 0.0f;
  result_.terminated[env] = 0;
  result_.truncated[env] = 0;
  ended_[env] = 0;
  diverged_[env].clear();
}

void BatchedEnv::startRound(int group) {
  const RobotTeam& team = *scene_->team();
  const int first = team.firstRow(group), k = team.robotsPerEnv();
  for (int e = first; e < first + k; ++e) {
    if (ended_[e]) continue;  // its episode ended in this step: that is its end
    // It waited since an earlier step: a stand-in episode ends, which no rate counts.
    ended_[e] = 1;
    outcome_[e] = static_cast<std::uint8_t>(Outcome::kWaited);
    result_.truncated[e] = 1;
    const float* obs = &result_.observations[static_cast<std::size_t>(e) * obs_dim_];
    std::copy(obs, obs + obs_dim_, &final_scratch_[static_cast<std::size_t>(e) * obs_dim_]);
    if (keepsFinalImages()) cameras_[0]->keepFinal(e);
  }
  scene_->beginRound(group);
  for (int e = first; e < first + k; ++e) resetEnv(e);
  scene_->endRound(group);
  // Each sees the others where they start (as reset() does).
  for (int e = first; e < first + k; ++e) {
    for (EnvSensor* sensor : sensors_) sensor->afterReset(e, scene_->sensed(e));
  }
  for (int e = first; e < first + k; ++e) {
    senseEnv(e);
    observeRow(e);
  }
}

}  // namespace jetbot_rl
