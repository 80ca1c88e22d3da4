// Several robots in one world (robots_per_env, robot_team.h): how BatchedEnv steps and places
// the robots of one env.
#include <Eigen/Geometry>
#include <algorithm>

#include "env/env_physics.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "scene/robot_team.h"
#include "sensors/env_sensor.h"

namespace jetbot_rl {

void BatchedEnv::stepTeam(int group, WorkerContext& context) {
  const int first = team_->firstRow(group), k = team_->robotsPerEnv();
  // Every robot's physics from where the others were when the step began (captured at the end
  // of the last step, at a reset and by setRootState()), then every scan where they all are
  // after it; a robot that starts anew is seen there from the next step.
  // A robot waiting for its round to end (rounds) stands still, unseen by the others.
  const auto active = [this](int e) { return !team_->waiting(e); };
  for (int e = first; e < first + k; ++e) {
    if (active(e)) stepPhysics(e, context);
  }
  for (int e = first; e < first + k; ++e) {
    if (active(e)) team_->capture(e, *envs_[e]);
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
  if (config_.team.rounds && team_->roundOver(group)) startRound(group);
}

void BatchedEnv::holdRow(int env) {
  result_.rewards[env] = 0.0f;
  result_.terminated[env] = 0;
  result_.truncated[env] = 0;
  ended_[env] = 0;
  diverged_[env].clear();
}

void BatchedEnv::startRound(int group) {
  const int first = team_->firstRow(group), k = team_->robotsPerEnv();
  for (int e = first; e < first + k; ++e) {
    if (ended_[e]) continue;  // its episode ended in this step: that is its end
    // It waited since an earlier step: a stand-in episode ends, which no rate counts.
    ended_[e] = 1;
    outcome_[e] = static_cast<std::uint8_t>(Outcome::kWaited);
    result_.truncated[e] = 1;
    const float* obs = &result_.observations[static_cast<std::size_t>(e) * obs_dim_];
    std::copy(obs, obs + obs_dim_, &final_scratch_[static_cast<std::size_t>(e) * obs_dim_]);
  }
  for (int e = first; e < first + k; ++e) team_->forget(e);
  for (int e = first; e < first + k; ++e) resetEnv(e);
  // Each sees the others where they start (as reset() does).
  for (int e = first; e < first + k; ++e) {
    for (EnvSensor* sensor : sensors_) sensor->afterReset(e, sensedEnv(e));
  }
  for (int e = first; e < first + k; ++e) {
    senseEnv(e);
    observeRow(e);
  }
}

void BatchedEnv::placeTeamRobot(int env) {
  EnvPhysics& physics = *envs_[env];
  EnvLayout& layout = layouts_[env];
  Rng& rng = rngs_[env];
  std::optional<Eigen::Vector2d> goal;
  double yaw = 0.0;
  team_->drawStart(env, rng, layout.start, goal, yaw);
  layout.obstacles.clear();
  if (drawer_) {
    WorldDraft draft;
    draft.start = layout.start;
    draft.goal = goal;
    std::vector<Eigen::Vector2d> keep_free{layout.start};
    drawer_->drawInWorld(env, rng, *world_, draft, keep_free);
    drawer_->layoutDrawn(env, *world_, layout);
  }
  if (yaw != 0.0) {  // facing the circle's centre, turned by the drawn initial_yaw
    RootState s = physics.rootState();
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
    s.orientation = turn * s.orientation;
    s.com_linear_velocity = turn * s.com_linear_velocity;
    s.angular_velocity = turn * s.angular_velocity;
    physics.setRootState(s);
  }
  physics.moveRobot(layout.start);
  team_->started(env);
  team_->capture(env, physics);
}

}  // namespace jetbot_rl
