#include "robot_team.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "env_physics.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A stand-in enters a robot's world this far [m] beyond where the two could touch within a
// control step at the speeds of its start (what they gain within it is centimetres).
constexpr double kNearMargin = 0.25;

}  // namespace

RobotTeam::RobotTeam(const TeamConfig& config, const WorldModel& world, int num_envs,
                     double robot_radius, double robot_height)
    : config_(config), world_(world), k_(config.robots_per_env), radius_(robot_radius) {
  const int rows = num_envs * k_;
  Obstacle footprint;
  footprint.shape = Obstacle::Shape::kCylinder;
  footprint.radius = robot_radius;
  footprint.height = robot_height;
  footprints_.assign(k_ - 1, footprint);
  position_.assign(rows, Eigen::Vector2d::Zero());
  velocity_.assign(rows, Eigen::Vector2d::Zero());
  placed_.assign(rows, 0);
  epoch_.assign(rows, 0);
  waiting_.assign(rows, 0);
  peers_.assign(rows, footprints_);
  near_.assign(rows, std::vector<std::uint8_t>(k_ - 1, 0));
  near_first_ = near_;
  seen_.assign(rows, std::vector<std::uint32_t>(k_ - 1, 0));
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
}

void RobotTeam::beginStep(int row, double dt) {
  const int first = (row / k_) * k_;
  std::vector<std::uint8_t>& near = near_[row];
  std::vector<std::uint8_t>& near_first = near_first_[row];
  const double own_speed = velocity_[row].norm();
  int slot = 0;
  for (int m = first; m < first + k_; ++m) {
    if (m == row) continue;
    const double reach = 2.0 * radius_ + kNearMargin + (velocity_[m].norm() + own_speed) * dt;
    near[slot] = placed_[m] && (position_[m] - position_[row]).squaredNorm() <= reach * reach;
    const bool jump = jumped(row, slot, m);  // seen now, near or not
    near_first[slot] = near[slot] && !jump;
    ++slot;
  }
}

const std::vector<Obstacle>& RobotTeam::peers(int row, double t) const {
  const int first = (row / k_) * k_;
  std::vector<Obstacle>& peers = peers_[row];
  int slot = 0;
  for (int m = first; m < first + k_; ++m) {
    if (m == row) continue;
    Obstacle& o = peers[slot++];
    o.center = position_[m] + t * velocity_[m];
    o.placed = placed_[m] != 0;
  }
  return peers;
}

bool RobotTeam::jumped(int row, int slot, int m) {
  std::uint32_t& seen = seen_[row][slot];
  if (seen == epoch_[m]) return false;
  seen = epoch_[m];
  return true;
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

void RobotTeam::drawStart(int row, Rng& rng, Eigen::Vector2d& start,
                          std::optional<Eigen::Vector2d>& goal, double& yaw) const {
  const double clearance = world_.startClearance();
  const Eigen::Vector2d centre(world_.config().spawn[0], world_.config().spawn[1]);
  const double r = config_.swap_radius;
  // A candidate's score: its distance to the nearest other robot, or -1 off the free floor.
  const auto score = [&](const Eigen::Vector2d& p) {
    return world_.staticClearance(p) < clearance ? -1.0 : mateDistance(row, p);
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
    return;
  }
  goal.reset();
  yaw = 0.0;
  double best = -1.0;
  for (int k = 0; k < world_.config().placement_tries && best < clearance; ++k) {
    const std::optional<Eigen::Vector2d> p = world_.drawFreePoint(rng, clearance);
    if (!p) break;
    const double s = mateDistance(row, *p);
    if (s > best) best = s, start = *p;
  }
  if (best < 0.0) {  // no free point drawn: the world's fallback start
    EnvLayout layout;
    world_.drawStart(rng, layout);
    start = layout.start;
  }
}

}  // namespace jetbot_rl
