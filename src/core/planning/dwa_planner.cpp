#include "jetbot_rl/planning/dwa_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

constexpr double kLethal = 253.0;  // costmap_2d's INSCRIBED_INFLATED_OBSTACLE

/// Distance from `p` to the polyline `path` [m] (to its one point, if one).
double distanceToPath(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i + 1 == path.size()) {
      best = std::min(best, (p - path[i]).norm());
      break;
    }
    const Eigen::Vector2d a = path[i], ab = path[i + 1] - a;
    const double t =
        ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

/// The distance to the nearest obstacle near the robot, per cell of kCell (costmap_2d's local
/// costmap, its cells' centres): what a trajectory point reads, in place of every return.
class LocalDistances {
 public:
  static constexpr double kCell = 0.05;  // [m]

  /// Cells within `reach` of `centre`, distances known up to `known` [m] (farther: infinity).
  LocalDistances(const Eigen::Vector2d& centre, double reach, double known,
                 const std::vector<Eigen::Vector2d>& obstacles)
      : origin_(centre - Eigen::Vector2d(reach, reach)),
        size_(std::max(1, static_cast<int>(std::ceil(2.0 * reach / kCell)))),
        distance_(static_cast<std::size_t>(size_) * size_, std::numeric_limits<float>::infinity()) {
    const int r = static_cast<int>(std::ceil(known / kCell)) + 1;
    for (const Eigen::Vector2d& o : obstacles) {
      const Eigen::Vector2d q = (o - origin_) / kCell;
      const int cx = static_cast<int>(std::floor(q.x())), cy = static_cast<int>(std::floor(q.y()));
      for (int y = std::max(0, cy - r); y <= std::min(size_ - 1, cy + r); ++y) {
        for (int x = std::max(0, cx - r); x <= std::min(size_ - 1, cx + r); ++x) {
          const Eigen::Vector2d centre_of = origin_ + kCell * Eigen::Vector2d(x + 0.5, y + 0.5);
          float& d = distance_[static_cast<std::size_t>(y) * size_ + x];
          d = std::min(d, static_cast<float>((o - centre_of).norm()));
        }
      }
    }
  }

  /// The distance at `p`'s cell, less half a cell's diagonal (never more than the truth) [m];
  /// infinity outside the cells.
  double at(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d q = (p - origin_) / kCell;
    if (!(q.x() >= 0.0 && q.y() >= 0.0 && q.x() < size_ && q.y() < size_)) {
      return std::numeric_limits<double>::infinity();
    }
    const float d =
        distance_[static_cast<std::size_t>(q.y()) * size_ + static_cast<std::size_t>(q.x())];
    return static_cast<double>(d) - 0.5 * std::sqrt(2.0) * kCell;
  }

 private:
  Eigen::Vector2d origin_;
  int size_;
  std::vector<float> distance_;
};

}  // namespace

void checkFieldRules(const DwaConfig& c) {
  if (c.min_vel_x > c.max_vel_x) {
    throwInvalid("dwa/min_vel_x", c.min_vel_x,
                 "must not exceed dwa/max_vel_x (" + std::to_string(c.max_vel_x) + ")");
  }
}

void setRobot(DwaInput& in, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
              const Eigen::Vector3d& linear_velocity, const Eigen::Vector3d& angular_velocity) {
  const Eigen::Vector3d forward = orientation * Eigen::Vector3d::UnitX();
  in.position = position.head<2>();
  in.yaw = std::atan2(forward.y(), forward.x());
  in.speed = (orientation.conjugate() * linear_velocity).x();
  in.yaw_rate = angular_velocity.z();
}

DwaPlanner::DwaPlanner(const DwaConfig& config, double robot_radius)
    : config_(config), robot_radius_(robot_radius + config.footprint_padding) {}

double DwaPlanner::obstacleCost(double distance) const {
  if (distance <= robot_radius_) return kLethal;
  if (distance > config_.inflation_radius) return 0.0;
  return 252.0 * std::exp(-config_.cost_scaling_factor * (distance - robot_radius_));
}

DwaCommand DwaPlanner::plan(const DwaInput& in) const {
  const DwaConfig& c = config_;
  DwaCommand best;
  if (in.path.empty()) return best;
  const Eigen::Vector2d& local_goal = in.local_goal;
  // What a trajectory can come near, as distances per local cell.
  const double known = std::max(c.inflation_radius, robot_radius_);
  const double reach = c.max_vel_x * c.sim_time + known;
  const LocalDistances distances(in.position, reach, known, in.obstacles);
  std::vector<Eigen::Vector2d> near;  // for the exact test at the footprint's edge
  for (const Eigen::Vector2d& o : in.obstacles) {
    if ((o - in.position).norm() <= reach + known) near.push_back(o);
  }
  // A cell's distance is low by up to a cell's diagonal: where that decides whether the footprint
  // touches (a gap a few centimetres wider than the robot), the returns decide exactly.
  const auto distanceAt = [&](const Eigen::Vector2d& p) {
    const double d = distances.at(p);
    if (d > robot_radius_ || d + std::sqrt(2.0) * LocalDistances::kCell <= robot_radius_) return d;
    double exact = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& o : near) exact = std::min(exact, (o - p).norm());
    return exact;
  };
  // The dynamic window: what the acceleration limits reach from the current velocity.
  const double v_lo = std::max(c.min_vel_x, in.speed - c.acc_lim_x * c.sim_period);
  const double v_hi = std::max(v_lo, std::min(c.max_vel_x, in.speed + c.acc_lim_x * c.sim_period));
  const double w_lo = std::max(-c.max_vel_theta, in.yaw_rate - c.acc_lim_theta * c.sim_period);
  const double w_hi =
      std::max(w_lo, std::min(c.max_vel_theta, in.yaw_rate + c.acc_lim_theta * c.sim_period));
  // As dwa_local_planner: the point ahead is drawn to the local goal moved forward_point_distance
  // further along the line to it (so that the centre is drawn onto the goal), and kept on the path
  // (alignment) until the robot is within forward_point_distance of the goal.
  const Eigen::Vector2d to_goal = local_goal - in.position;
  const Eigen::Vector2d front_goal =
      to_goal.norm() > 0.0
          ? Eigen::Vector2d(local_goal + c.forward_point_distance * to_goal.normalized())
          : local_goal;
  const double alignment =
      (in.path.back() - in.position).norm() > c.forward_point_distance ? 1.0 : 0.0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int i = 0; i < c.vx_samples; ++i) {
    const double v = c.vx_samples > 1 ? v_lo + (v_hi - v_lo) * i / (c.vx_samples - 1) : v_hi;
    for (int j = 0; j < c.vth_samples; ++j) {
      const double w = c.vth_samples > 1 ? w_lo + (w_hi - w_lo) * j / (c.vth_samples - 1) : 0.0;
      // Forward-simulated at constant velocity, a point every sim_granularity (of travel or of
      // turning at the footprint's edge).
      const double travel = std::max(std::abs(v), std::abs(w) * robot_radius_) * c.sim_time;
      const int steps = std::max(1, static_cast<int>(std::ceil(travel / c.sim_granularity)));
      const double dt = c.sim_time / steps;
      Eigen::Vector2d p = in.position;
      double yaw = in.yaw, occupied = 0.0;
      for (int k = 1; k <= steps && occupied < kLethal; ++k) {
        p += v * dt * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
        yaw += w * dt;
        occupied = std::max(occupied, obstacleCost(distanceAt(p)));
      }
      if (occupied >= kLethal) continue;
      const Eigen::Vector2d front =
          p + c.forward_point_distance * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
      const double cost =
          0.5 * c.path_distance_bias *
              (distanceToPath(p, in.path) + alignment * distanceToPath(front, in.path)) +
          0.5 * c.goal_distance_bias * ((p - local_goal).norm() + (front - front_goal).norm()) +
          c.occdist_scale * occupied;
      if (cost < best_cost) {
        best_cost = cost;
        best = {v, w, true};
      }
    }
  }
  if (best.found) return best;
  // Nothing clear: turn in place towards the local goal.
  const Eigen::Vector2d to = local_goal - in.position;
  const double error = std::remainder(std::atan2(to.y(), to.x()) - in.yaw, 2.0 * kPi);
  best.speed = 0.0;
  best.yaw_rate = error >= 0.0 ? c.max_vel_theta : -c.max_vel_theta;
  return best;
}

}  // namespace jetbot_rl
