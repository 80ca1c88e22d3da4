#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/scene/team_config.h"
#include "jetbot_rl/world/world_model.h"
#include "scene/moving_bodies.h"

namespace jetbot_rl {

class EnvPhysics;

/**
 * Several robots in one world (robots_per_env K > 1): robot k of env e is row e K + k of the
 * batch, with its own Bullet world, as every row. The others of its env enter that world as
 * kinematic stand-ins of their footprints (as movers do), moved along their velocities over a
 * control step from where they were when it began, and its scan sees them where they are after
 * it. A group (env) is stepped by one thread in row order, so that it is deterministic. To a
 * robot the others are MovingBodies, as people are.
 */
class RobotTeam final : public MovingBodies {
 public:
  /// ConfigError naming robots_per_env or swap_radius when the K starts do not fit the world.
  /// `physics_dt` [s]: the physics step (moveIn()).
  RobotTeam(const TeamConfig& config, const WorldModel& world, int num_envs, double robot_radius,
            double robot_height, double physics_dt);

  int robotsPerEnv() const { return k_; }
  /// Rows of env `env`: [env K, env K + K).
  int firstRow(int env) const { return env * k_; }
  /// The robots' footprints for a robot's world (cylinders; their shapes for EnvPhysics).
  const std::vector<Obstacle>& footprints() const { return footprints_; }

  /// Records where `row`'s robot is and how fast it moves (after a step or a reset).
  void capture(int row, const EnvPhysics& physics);
  /// Records that `row`'s robot started anew (a reset: it jumped to its start).
  void started(int row) {
    ++epoch_[row];
    placed_[row] = 1;
    waiting_[row] = 0;
  }
  /// Marks `row` as not yet placed: a start drawn now ignores it (a reset of several rows).
  void forget(int row) { placed_[row] = 0; }
  /// Rounds: `row`'s episode ended; it waits, out of the others' worlds, until started() again.
  void wait(int row) {
    placed_[row] = 0;
    waiting_[row] = 1;
  }
  bool waiting(int row) const { return waiting_[row] != 0; }
  /// True when every robot of env `env` waits: its round is over.
  bool roundOver(int env) const;
  /// Once per control step of `dt` [s], before its physics: which of the other robots of
  /// `row`'s world are near enough to touch it within the step (from their captures), and which
  /// started anew since `row`'s last step (parked for its first physics step, so that the jump is
  /// no velocity). Calls for rows of one env come from one thread. False when no stand-in can
  /// be in the robot's Bullet world in this step (none near now or at its last step): nothing
  /// to move.
  bool beginStep(int row, double dt) override;
  /// Moves the near stand-ins of the others in `physics` (row `row`'s) to where they are at the
  /// end of physics step `substep`, parks those no longer near.
  void moveIn(int row, int substep, EnvPhysics& physics) override;
  /// The others where they are now (peers() at t 0).
  const std::vector<Obstacle>& bodies(int row) const override { return peers(row, 0.0); }
  /// The other robots of `row`'s world, `t` [s] after their capture along their velocities;
  /// with `only`, just the slots it marks (the others hold nothing to read). Valid until the
  /// next call for a row of the same env.
  const std::vector<Obstacle>& peers(int row, double t,
                                     const std::vector<std::uint8_t>* only = nullptr) const;
  /// The near flags of beginStep() for physics step `substep` of the control step, per
  /// peers() slot. Valid until the next beginStep() for a row of the same env.
  const std::vector<std::uint8_t>& near(int row, int substep) const {
    return substep == 0 ? near_first_[row / k_] : near_[row / k_];
  }
  /// Draws `row`'s start from its stream, clear of the others placed in its world by
  /// world/start_clearance: circle swap (its own point when free, else a free point of the
  /// circle) with `goal` the opposite point and `yaw` facing the centre [rad]; else a free
  /// point of the region (no goal, yaw 0). The clearest draw stands in when none is free.
  /// With `others` (the people of its world), clear of their outlines too. With `fits` (a
  /// generated layout's free floor), the region's points it accepts stand for the free points.
  /// False when no draw was free (the stand-in is then the clearest, or the world's fallback).
  bool drawStart(int row, Rng& rng, Eigen::Vector2d& start, std::optional<Eigen::Vector2d>& goal,
                 double& yaw, const std::vector<Obstacle>* others = nullptr,
                 const std::function<bool(const Eigen::Vector2d&)>& fits = nullptr) const;

 private:
  /// Least distance from `p` to the placed robots of `row`'s world other than it [m].
  double mateDistance(int row, const Eigen::Vector2d& p) const;

  TeamConfig config_;
  const WorldModel& world_;
  int k_;
  double radius_;
  double physics_dt_;
  std::vector<Obstacle> footprints_;                   // K - 1 cylinders
  std::vector<Eigen::Vector2d> position_;              // per row [m]
  std::vector<Eigen::Vector2d> velocity_;              // per row [m/s]
  std::vector<double> speed_;                          // per row: |velocity_| [m/s]
  std::vector<std::uint8_t> any_near_;                 // per row: at its last beginStep()
  std::vector<std::uint8_t> placed_;                   // per row: reset at least once
  std::vector<std::uint32_t> epoch_;                   // per row: its starts
  std::vector<std::uint8_t> waiting_;                  // per row: rounds, ended and waiting
  mutable std::vector<std::vector<Obstacle>> peers_;   // per env: a row's K - 1 others
  std::vector<std::vector<std::uint8_t>> near_;        // per env: a row's, per slot
  std::vector<std::vector<std::uint8_t>> near_first_;  // per env: near_ less the jumped
  std::vector<std::uint32_t> seen_;                    // per row and slot: the others' epochs seen
};

}  // namespace jetbot_rl
