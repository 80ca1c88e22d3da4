#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

class EnvPhysics;

/// Where the robots of one world stand when its control step begins: what the bodies that move
/// in it plan their step from.
struct WorldStep {
  int world = 0;                            ///< The env (world) index.
  const EnvLayout* layout = nullptr;        ///< Its layout of the episode (obstacles).
  const Eigen::Vector2d* robots = nullptr;  ///< Its robots' root positions [m], env frame.
  const std::uint8_t* present = nullptr;    ///< Per robot: 1 when in the world (null: all).
  int num_robots = 0;                       ///< Robots of the world (robots_per_env).
  double dt = 0.0;                          ///< The control step [s].
};

/**
 * Other bodies that move in a robot's world: people and carts (PeopleBodies) or the other
 * robots of a team (RobotTeam). Each row (robot) has its own Bullet world, in which they are
 * kinematic bodies; its sensors see them where they stand. BatchedEnv steps every kind the same
 * way, so that several kinds share one world: beginWorldStep() once per world and control step,
 * then per row beginStep() and moveIn() at each physics step. Calls for the rows of one world
 * come from one thread, in row order.
 */
class MovingBodies {
 public:
  virtual ~MovingBodies() = default;
  /// Once per control step of world `step.world`, before any of its robots' physics.
  virtual void beginWorldStep(const WorldStep& step) { (void)step; }
  /// Once per control step of `dt` [s] of row `row`, before its physics: false when none of
  /// them can be in its Bullet world in this step (nothing to move).
  virtual bool beginStep(int row, double dt) = 0;
  /// Moves them in `physics` (row `row`'s) to where they are at the end of physics step
  /// `substep` of the control step (those far from the robot are parked).
  virtual void moveIn(int row, int substep, EnvPhysics& physics) = 0;
  /// Where they stand now, as row `row`'s sensors see them (env frame). Valid until the next
  /// call for a row of the same world.
  virtual const std::vector<Obstacle>& bodies(int row) const = 0;
};

}  // namespace jetbot_rl
