#pragma once

#include <cstdint>
#include <vector>

#include "jetbot_rl/scene/movers.h"
#include "scene/moving_bodies.h"

namespace jetbot_rl {

/**
 * The movers (people and carts, MoverSet) of each world as MovingBodies: they walk once per
 * world and control step, planned from where all the world's robots stand, and every robot of
 * the world meets them where they are at each physics step. Mover env index = world index.
 */
class PeopleBodies final : public MovingBodies {
 public:
  /// `robots_per_world` rows per world (row r in world r / robots_per_world); `decimation`
  /// physics steps of `physics_dt` [s] per control step.
  PeopleBodies(MoverSet& movers, int robots_per_world, int decimation, double physics_dt);

  void beginWorldStep(const WorldStep& step) override;
  bool beginStep(int row, double dt) override;
  void moveIn(int row, int substep, EnvPhysics& physics) override;
  const std::vector<Obstacle>& bodies(int row) const override {
    return movers_.bodies(row / robots_per_world_);
  }
  /// Gives row `row`'s physics the shapes of its world's movers (after they were drawn).
  void enter(int row, EnvPhysics& physics) const;

 private:
  MoverSet& movers_;
  int robots_per_world_;
  int decimation_;
  double physics_dt_;
  std::vector<std::vector<std::uint8_t>> near_;  // per row, per mover
  // Several robots per world: per world, the movers at the end of each physics step of the
  // control step (every robot's physics meets them there); one robot walks them in place.
  std::vector<std::vector<std::vector<Obstacle>>> at_substep_;
};

}  // namespace jetbot_rl
