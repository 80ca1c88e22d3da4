// Several robots in one world (robots_per_env, robot_team.h): how BatchedEnv steps and places
// the robots of one env.
#include <Eigen/Geometry>

#include "env_physics.h"
#include "jetbot_rl/batched_env.h"
#include "jetbot_rl/task_capabilities.h"
#include "robot_team.h"

namespace jetbot_rl {

void BatchedEnv::stepTeam(int group, WorkerContext& context) {
  const int first = team_->firstRow(group), k = team_->robotsPerEnv();
  // Every robot's physics from where the others were when the step began (captured at the end
  // of the last step, at a reset and by setRootState()), then every scan where they all are
  // after it; a robot that starts anew is seen there from the next step.
  for (int e = first; e < first + k; ++e) stepPhysics(e, context);
  for (int e = first; e < first + k; ++e) team_->capture(e, *envs_[e]);
  for (int e = first; e < first + k; ++e) sensePhysics(e);
  for (int e = first; e < first + k; ++e) finishStep(e);
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
