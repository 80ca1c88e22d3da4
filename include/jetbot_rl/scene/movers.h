#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/scene/mover_config.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/**
 * The moving obstacles of every env of a batch (docs/world.md, "Moving obstacles"): people
 * (cylinders) and carts (boxes) drawn at each reset in the env's free space from the env's own
 * mover stream, heading for waypoints drawn in free space with a clear straight line to them.
 * plan() sets each mover's velocity for a control step (MoverRule), advance() moves it on by a
 * physics step; the physics makes them kinematic bodies, the scanner casts them. An env's movers
 * depend only on its seed, its layouts and its robot's positions, never on the thread.
 */
class MoverSet {
 public:
  /// ConfigError naming movers/num_people or movers/num_carts when there is no world, no
  /// bounded region, or too little free space for them. `config` is valid (the env validates
  /// its EnvConfig once).
  MoverSet(const MoverConfig& config, const WorldModel& world, int num_envs, std::uint64_t seed);

  const MoverConfig& config() const { return config_; }
  /// Movers per env (placed or not).
  int count() const { return config_.count(); }
  /// Envs (worlds) it walks movers in.
  std::size_t numEnvs() const { return bodies_.size(); }
  /// Restarts env `env`'s mover stream from `seed` (a reset with a seed).
  void reseed(int env, std::uint64_t seed);
  /// Draws env `env`'s movers for the episode of `layout`: the people, then the carts, none
  /// within start_clearance of the start; a mover that does not fit in world/placement_tries
  /// draws is left out (placed false). Returns how many were left out.
  int reset(int env, const EnvLayout& layout) { return reset(env, layout, &layout.start, 1); }
  /// As above, none within start_clearance of any of the `count` points `keep_clear` [m] (the
  /// starts of the robots of its world).
  int reset(int env, const EnvLayout& layout, const Eigen::Vector2d* keep_clear, int count);
  /// Sets env `env`'s velocities for a control step of `dt` [s] with the robot's root at
  /// `robot` [m] (env frame), and nearRobot(); draws new waypoints for those that arrived.
  void plan(int env, const EnvLayout& layout, const Eigen::Vector2d& robot, double dt) {
    plan(env, layout, &robot, nullptr, 1, dt);
    markNear(env, robot, dt, near_[env]);
  }
  /// As above with the `count` robots of its world at `robots` [m] (each avoided where
  /// `present` is null or 1); nearRobot() is left as it was.
  void plan(int env, const EnvLayout& layout, const Eigen::Vector2d* robots,
            const std::uint8_t* present, int count, double dt);
  /// Per mover of env `env`: 1 in `near` when it may touch a robot at `robot` [m] within a
  /// control step of `dt` [s] at the velocities of the last plan().
  void markNear(int env, const Eigen::Vector2d& robot, double dt,
                std::vector<std::uint8_t>& near) const;
  /// Moves env `env`'s movers on by their velocities for `dt` [s] (a physics step).
  void advance(int env, double dt);
  /// Env `env`'s movers as they stand: the people, then the carts (env frame).
  const std::vector<Obstacle>& bodies(int env) const { return bodies_[env]; }
  /// Per mover of env `env`: 1 when it may touch the robot within the control step of the last
  /// plan() (the physics moves only those).
  const std::vector<std::uint8_t>& nearRobot(int env) const { return near_[env]; }
  /// Env `env`'s mover `k`'s velocity [m/s].
  const Eigen::Vector2d& velocity(int env, int k) const { return state_[env][k].velocity; }
  /// Env `env`'s mover `k`'s waypoint [m].
  const Eigen::Vector2d& waypoint(int env, int k) const { return state_[env][k].waypoint; }
  /// Env `env`'s mover `k`'s walking speed [m/s].
  double speed(int env, int k) const { return state_[env][k].speed; }

 private:
  struct State {
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s]
    Eigen::Vector2d waypoint = Eigen::Vector2d::Zero();  // [m]
    double speed = 0.0;                                  // [m/s]
    bool has_waypoint = false;
  };
  /// Draws `p` in the region from `env`'s stream; true when it is `radius` clear of the world
  /// and `layout`.
  bool drawClearPoint(int env, double radius, const EnvLayout& layout, Eigen::Vector2d& p);
  /// True when a disc of `radius` moves from `a` to `b` without touching the world or `layout`.
  bool segmentClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius,
                    const EnvLayout& layout) const;
  void drawWaypoint(int env, int k, const EnvLayout& layout, int tries);
  /// The social force's acceleration on env `env`'s mover `k` [m/s^2].
  Eigen::Vector2d socialForce(int env, int k, const EnvLayout& layout,
                              const Eigen::Vector2d* robots, const std::uint8_t* present,
                              int count) const;

  MoverConfig config_;
  const WorldModel& world_;
  std::vector<std::vector<Obstacle>> bodies_;    // per env, per mover
  std::vector<std::vector<State>> state_;        // likewise
  std::vector<std::vector<std::uint8_t>> near_;  // likewise: nearRobot()
  std::vector<Rng> rngs_;                        // per env: its mover stream
  Eigen::AlignedBox2d region_;                   // where they start and head
};

}  // namespace jetbot_rl
