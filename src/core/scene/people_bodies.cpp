// The movers of each world as bodies that move in its robots' worlds (PeopleBodies).
#include "scene/people_bodies.h"

#include "env/env_physics.h"

namespace jetbot_rl {

PeopleBodies::PeopleBodies(MoverSet& movers, int robots_per_world, int decimation,
                           double physics_dt)
    : movers_(movers),
      robots_per_world_(robots_per_world),
      decimation_(decimation),
      physics_dt_(physics_dt) {
  const int worlds = static_cast<int>(movers_.numEnvs());
  near_.assign(static_cast<std::size_t>(worlds) * robots_per_world_,
               std::vector<std::uint8_t>(movers_.count(), 0));
  if (robots_per_world_ > 1) {
    at_substep_.assign(worlds, std::vector<std::vector<Obstacle>>(decimation_));
  }
}

void PeopleBodies::beginWorldStep(const WorldStep& step) {
  // Their velocities for the control step, from where every robot of the world stands, and
  // which may touch each robot within it.
  movers_.plan(step.world, *step.layout, step.robots, step.present, step.num_robots, step.dt);
  for (int r = 0; r < step.num_robots; ++r) {
    movers_.markNear(step.world, step.robots[r], step.dt,
                     near_[static_cast<std::size_t>(step.world) * robots_per_world_ + r]);
  }
  if (robots_per_world_ == 1) return;  // moveIn() walks them on
  // Each robot's physics meets them at every physics step: walked on once, kept per step.
  std::vector<std::vector<Obstacle>>& at = at_substep_[step.world];
  for (int k = 0; k < decimation_; ++k) {
    movers_.advance(step.world, physics_dt_);
    at[k] = movers_.bodies(step.world);
  }
}

bool PeopleBodies::beginStep(int row, double dt) {
  (void)row;
  (void)dt;
  return true;  // near or not, each is moved or parked at every physics step
}

void PeopleBodies::moveIn(int row, int substep, EnvPhysics& physics) {
  const int world = row / robots_per_world_;
  if (robots_per_world_ == 1) {
    movers_.advance(world, physics_dt_);
    physics.moveMovers(movers_.bodies(world), near_[row]);
    return;
  }
  physics.moveMovers(at_substep_[world][substep], near_[row]);
}

void PeopleBodies::enter(int row, EnvPhysics& physics) const {
  physics.setMovers(movers_.bodies(row / robots_per_world_));
}

}  // namespace jetbot_rl
