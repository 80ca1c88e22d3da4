#include "scene/robot_team.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "env/env_physics.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

// A stand-in enters a robot's world this far [m] beyond where the two could touch within a
// control step at the speeds of its start (what they gain within it is centimetres).
constexpr double kStandInMargin = 0.25;

}  // namespace

RobotTeam::RobotTeam(const TeamConfig& config, const WorldModel& world, int num_envs,
                     double robot_radius, double robot_height, double physics_dt)
    : config_(config),
      world_(world),
      k_(config.robots_per_env),
      radius_(robot_radius),
      physics_dt_(physics_dt) {
  const int rows = num_envs * k_;
  Obstacle footprint;
  footprint.shape = Obstacle::Shape::kCylinder;
  footprint.radius = robot_radius;
  footprint.height = robot_height;
  footprints_.assign(k_ - 1, footprint);
  position_.assign(rows, Eigen::Vector2d::Zero());
  velocity_.assign(rows, Eigen::Vector2d::Zero());
  speed_.assign(rows, 0.0);
  any_near_.assign(rows, 0);
  placed_.assign(rows, 0);
  epoch_.assign(rows, 0);
  waiting_.assign(rows, 0);
  // Scratch per env, not per row: a row's others are needed only while its env steps it, and
  // one env's scratch stays in the cache through its K rows (per row it missed at every step).
  peers_.assign(num_envs, footprints_);
  near_.assign(num_envs, std::vector<std::uint8_t>(k_ - 1, 0));
  near_first_ = near_;
  seen_.assign(static_cast<std::size_t>(rows) * (k_ - 1), 0);
  if (config_.swap_radius <= 0.0) return;
  // Every robot's own point must be a start: free of the world, and of its neighbours.
  const double r = config_.swap_radius, clearance = world_.startClearance();
  const double chord = 2.0 * r * std::sin(kPi / k_);
  if (k_ > 1 && chord < clearance) {
    throwInvalid("robots_per_env", k_,
                 "too many robots for the circle: neighbours " + std::to_string(chord) +
                     " m apart on swap_radius " + std::to_string(r) +
                     " m, less than world/start_clearance " + std::to_string(clearance) + " m");
  }
  const Eigen::Vector2d centre(world_.config().spawn[0], world_.config().spawn[1]);
  for (int k = 0; k < k_; ++k) {
    const double a = 2.0 * kPi * k / k_;
    const Eigen::Vector2d p = centre + r * Eigen::Vector2d(std::cos(a), std::sin(a));
    if (world_.staticClearance(p) < clearance) {
      throwInvalid("swap_radius", r,
                   "robot " + std::to_string(k) + "'s point (" + std::to_string(p.x()) + ", " +
                       std::to_string(p.y()) + ") is within world/start_clearance " +
                       std::to_string(clearance) + " m of a wall or the map");
    }
  }
}

void RobotTeam::capture(int row, const EnvPhysics& physics) {
  const RootState s = physics.rootState();
  position_[row] = s.position.head<2>();
  velocity_[row] = s.com_linear_velocity.head<2>();
  speed_[row] = velocity_[row].norm();
}

bool RobotTeam::beginStep(int row, double dt) {
  const int first = (row / k_) * k_;
  // Plain pointers and locals: a store through a byte pointer could alias any member, which
  // would reload them all at every slot.
  std::uint8_t* near = near_[row / k_].data();
  std::uint8_t* near_first = near_first_[row / k_].data();
  std::uint32_t* seen = &seen_[static_cast<std::size_t>(row) * (k_ - 1)];
  const Eigen::Vector2d* position = position_.data();
  const double* speed = speed_.data();
  const std::uint8_t* placed = placed_.data();
  const std::uint32_t* epoch = epoch_.data();
  const Eigen::Vector2d own = position[row];
  const double base = 2.0 * radius_ + kStandInMargin + speed[row] * dt;
  int slot = 0;
  bool any = false;
  for (int m = first; m < first + k_; ++m) {
    if (m == row) continue;
    const double reach = base + speed[m] * dt;
    const bool is_near = placed[m] && (position[m] - own).squaredNorm() <= reach * reach;
    const bool jumped = seen[slot] != epoch[m];  // started anew since last seen, near or not
    seen[slot] = epoch[m];
    near[slot] = is_near;
    near_first[slot] = is_near && !jumped;
    any = any || is_near;
    ++slot;
  }
  // A stand-in near at the last step may still be in its world: this step parks it.
  const bool move = any || any_near_[row];
  any_near_[row] = any;
  return move;
}

void RobotTeam::moveIn(int row, int substep, EnvPhysics& physics) {
  const std::vector<std::uint8_t>& only = near(row, substep);
  physics.movePeers(peers(row, (substep + 1) * physics_dt_, &only), only);
}

const std::vector<Obstacle>& RobotTeam::peers(int row, double t,
                                              const std::vector<std::uint8_t>* only) const {
  const int first = (row / k_) * k_;
  std::vector<Obstacle>& peers = peers_[row / k_];
  int slot = 0;
  for (int m = first; m < first + k_; ++m) {
    if (m == row) continue;
    if (!only || (*only)[slot]) {
      Obstacle& o = peers[slot];
      o.center = position_[m] + t * velocity_[m];
      o.placed = placed_[m] != 0;
    }
    ++slot;
  }
  return peers;
}

bool RobotTeam::roundOver(int env) const {
  const int first = firstRow(env);
  return std::all_of(waiting_.begin() + first, waiting_.begin() + first + k_,
                     [](std::uint8_t w) { return w != 0; });
}

double RobotTeam::mateDistance(int row, const Eigen::Vector2d& p) const {
  const int first = (row / k_) * k_;
  double d = std::numeric_limits<double>::infinity();
  for (int m = first; m < first + k_; ++m) {
    if (m != row && placed_[m]) d = std::min(d, (position_[m] - p).norm());
  }
  return d;
}

bool RobotTeam::drawStart(int row, Rng& rng, Eigen::Vector2d& start,
                          std::optional<Eigen::Vector2d>& goal, double& yaw,
                          const std::vector<Obstacle>* others,
                          const std::function<bool(const Eigen::Vector2d&)>& fits) const {
  const double clearance = world_.startClearance();
  // Distance from `p` to the nearest other robot or to the outline of the nearest other body.
  const auto free_of = [&](const Eigen::Vector2d& p) {
    double d = mateDistance(row, p);
    for (std::size_t i = 0; others && i < others->size(); ++i) {
      const Obstacle& o = (*others)[i];
      if (o.placed) d = std::min(d, std::max(0.0, (o.center - p).norm() - o.boundingRadius()));
    }
    return d;
  };
  const Eigen::Vector2d centre(world_.config().spawn[0], world_.config().spawn[1]);
  const double r = config_.swap_radius;
  // A candidate's score: its distance to the nearest other robot, or -1 off the free floor.
  const auto score = [&](const Eigen::Vector2d& p) {
    return world_.staticClearance(p) < clearance ? -1.0 : free_of(p);
  };
  double angle = 2.0 * kPi * (row % k_) / k_;
  const auto onCircle = [&](double a) {
    return Eigen::Vector2d(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  };
  if (r > 0.0) {
    double best = score(onCircle(angle));
    for (int k = 0; k < world_.config().placement_tries && best < clearance; ++k) {
      const double a = 2.0 * kPi * rng.uniform();
      const double s = score(onCircle(a));
      if (s > best) best = s, angle = a;
    }
    start = onCircle(angle);
    goal = onCircle(angle + kPi);
    yaw = angle + kPi;
    return best >= 0.0;
  }
  goal.reset();
  yaw = 0.0;
  double best = -1.0;
  const Eigen::AlignedBox2d& region = world_.region();
  for (int k = 0; k < world_.config().placement_tries && best < clearance; ++k) {
    std::optional<Eigen::Vector2d> p;
    if (fits) {  // one candidate a try
      const Eigen::Vector2d q(uniform(rng, region.min().x(), region.max().x()),
                              uniform(rng, region.min().y(), region.max().y()));
      if (!fits(q)) continue;
      p = q;
    } else {
      p = world_.drawFreePoint(rng, clearance);
      if (!p) break;
    }
    const double s = free_of(*p);
    if (s > best) best = s, start = *p;
  }
  if (best < 0.0) {  // no free point drawn: the world's fallback start
    EnvLayout layout;
    world_.drawStart(rng, layout);
    start = layout.start;
    return false;
  }
  return true;
}

}  // namespace jetbot_rl
