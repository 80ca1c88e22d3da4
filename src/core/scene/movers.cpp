// Moving obstacles: where they start, where they head, how they walk (MoverSet).
#include "jetbot_rl/scene/movers.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

// An env's mover stream: the stream of env id e + kMoverStream (not its layouts' or its scan's).
constexpr std::uint64_t kMoverStream = streams::kMovers;
// Room a mover keeps from the world and from the other movers where it is drawn [m].
constexpr double kMargin = 0.05;
// Waypoint draws per mover and control step once it has arrived; without a clear one it stands
// for the step and tries again at the next.
constexpr int kWaypointTries = 20;
// Forces beyond this many fall-off lengths are left out (exp(-6) < 0.3 %).
constexpr double kForceReach = 6.0;
// A mover walks no faster than this times its speed (Helbing and Molnar's v_max).
constexpr double kMaxSpeedFactor = 1.3;
// Step of the clearance's central differences, the direction the world pushes from [m].
constexpr double kGradientStep = 0.02;
// Points tested along a straight line to a waypoint, one per this length [m].
constexpr double kSegmentStep = 0.05;
// A mover is near the robot (moved in the physics) when the gap between them is below what it
// walks in the control step plus this much, or kNearPerSecond per second of the step if more:
// room for the robot's own way [m].
constexpr double kNearMargin = 1.0;
constexpr double kNearPerSecond = 5.0;  // [m/s]
// Points sampled at start-up to estimate the free part of the region.
constexpr int kAreaSamples = 4000;

/// A point drawn uniformly in `box`.
Eigen::Vector2d pointIn(const Eigen::AlignedBox2d& box, Rng& rng) {
  const double x = box.min().x() + box.sizes().x() * rng.uniform();
  return {x, box.min().y() + box.sizes().y() * rng.uniform()};
}

double uniformIn(Rng& rng, const std::vector<double>& range) {
  return range[0] + (range[1] - range[0]) * rng.uniform();
}

/// Distance from `p` to `o`'s outline (negative inside) [m], and in `normal` the unit direction
/// from its nearest point to `p` (outwards).
double outward(const Obstacle& o, const Eigen::Vector2d& p, Eigen::Vector2d& normal) {
  const Eigen::Vector2d rel = p - o.center;
  if (o.shape == Obstacle::Shape::kCylinder) {
    const double d = rel.norm();
    normal = d > 1e-9 ? Eigen::Vector2d(rel / d) : Eigen::Vector2d::UnitX();
    return d - o.radius;
  }
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const Eigen::Vector2d q(c * rel.x() + s * rel.y(), -s * rel.x() + c * rel.y());
  const Eigen::Vector2d outside = q.cwiseAbs() - o.half_extents;
  Eigen::Vector2d local;
  double d = 0.0;
  if (outside.x() > 0.0 || outside.y() > 0.0) {
    local = q - q.cwiseMax(-o.half_extents).cwiseMin(o.half_extents);
    d = local.norm();
    local /= d;
  } else {  // inside: out through the nearest side
    const bool x = outside.x() > outside.y();
    local = x ? Eigen::Vector2d(q.x() < 0 ? -1.0 : 1.0, 0.0)
              : Eigen::Vector2d(0.0, q.y() < 0 ? -1.0 : 1.0);
    d = std::max(outside.x(), outside.y());
  }
  normal = Eigen::Vector2d(c * local.x() - s * local.y(), s * local.x() + c * local.y());
  return d;
}

}  // namespace

MoverSet::MoverSet(const MoverConfig& config, const WorldModel& world, int num_envs,
                   std::uint64_t seed)
    : config_(config), world_(world), bodies_(num_envs), state_(num_envs), near_(num_envs) {
  const char* field = config_.num_people > 0 ? "movers/num_people" : "movers/num_carts";
  const int n = config_.count();
  if (!config_.region.empty()) {
    const std::vector<double>& r = config_.region;
    if (r.size() != 4 || r[0] >= r[2] || r[1] >= r[3]) {
      throwInvalid("movers/region", listText(r),
                   "must be [x_min, y_min, x_max, y_max] with min < max, or []");
    }
    region_ = Eigen::AlignedBox2d(Eigen::Vector2d(r[0], r[1]), Eigen::Vector2d(r[2], r[3]));
    if (!world_.region().isEmpty() && !world_.region().contains(region_)) {
      const Eigen::AlignedBox2d& w = world_.region();
      throwInvalid(
          "movers/region", listText(r),
          "must lie inside the world's region " +
              listText(std::vector<double>{w.min().x(), w.min().y(), w.max().x(), w.max().y()}));
    }
  } else {
    region_ = world_.region();
  }
  const Eigen::AlignedBox2d& region = region_;
  if (region.isEmpty()) {
    throwInvalid(field, n, "movers walk in world/region (or the arena, or the map): none is set");
  }
  // The free part of the region (a fixed stream: the same estimate on every run), against the
  // discs the movers need at their largest.
  Rng probe(seed, kMoverStream - 1);
  int free = 0;
  for (int i = 0; i < kAreaSamples; ++i) {
    if (world_.staticClearance(pointIn(region, probe)) > 0.0) ++free;
  }
  const double free_area = region.volume() * free / kAreaSamples;
  const double person = config_.person_radius[1] + kMargin;
  const double cart = 0.5 * std::hypot(config_.cart_size[1], config_.cart_size[1]) + kMargin;
  const double needed =
      kPi * (config_.num_people * person * person + config_.num_carts * cart * cart);
  if (free == 0 && !config_.region.empty()) {
    throwInvalid("movers/region", listText(config_.region),
                 "has no free point: the movers would stand in the world");
  }
  if (needed > 0.5 * free_area) {
    throwInvalid(field, n,
                 "the movers' discs at their largest (" + std::to_string(needed) +
                     " m^2) cover more than half the free part of the region (" +
                     std::to_string(free_area) + " m^2): fewer or smaller movers");
  }
  for (int e = 0; e < num_envs; ++e) {
    rngs_.emplace_back(seed, e + kMoverStream);
    bodies_[e].resize(n);
    state_[e].resize(n);
    near_[e].assign(n, 0);
    for (int k = 0; k < n; ++k) {
      Obstacle& b = bodies_[e][k];
      b.shape = k < config_.num_people ? Obstacle::Shape::kCylinder : Obstacle::Shape::kBox;
      b.height = config_.height;
      b.placed = false;
    }
  }
}

void MoverSet::reseed(int env, std::uint64_t seed) { rngs_[env] = Rng(seed, env + kMoverStream); }

bool MoverSet::drawClearPoint(int env, double radius, const EnvLayout& layout, Eigen::Vector2d& p) {
  p = pointIn(region_, rngs_[env]);
  return world_.isClear(p, radius, layout.obstacles);
}

bool MoverSet::segmentClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius,
                            const EnvLayout& layout) const {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / kSegmentStep));
  for (int i = 1; i <= steps; ++i) {
    if (!world_.isClear(a + (b - a) * (static_cast<double>(i) / steps), radius, layout.obstacles)) {
      return false;
    }
  }
  return true;
}

void MoverSet::drawWaypoint(int env, int k, const EnvLayout& layout, int tries) {
  const Obstacle& b = bodies_[env][k];
  State& s = state_[env][k];
  const double r = b.boundingRadius() + kMargin;
  Eigen::Vector2d w;
  for (int t = 0; t < tries; ++t) {
    if (drawClearPoint(env, r, layout, w) && segmentClear(b.center, w, r, layout)) {
      s.waypoint = w;
      s.has_waypoint = true;
      return;
    }
  }
  s.has_waypoint = false;
}

int MoverSet::reset(int env, const EnvLayout& layout, const Eigen::Vector2d* keep_clear,
                    int count) {
  const int tries = world_.config().placement_tries;
  Rng& rng = rngs_[env];
  int given_up = 0;
  std::vector<Obstacle>& bodies = bodies_[env];
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    Obstacle& b = bodies[k];
    State& s = state_[env][k];
    if (b.shape == Obstacle::Shape::kCylinder) {
      b.radius = uniformIn(rng, config_.person_radius);
    } else {
      b.half_extents = 0.5 * Eigen::Vector2d(uniformIn(rng, config_.cart_size),
                                             uniformIn(rng, config_.cart_size));
      b.yaw = (2.0 * rng.uniform() - 1.0) * kPi;
    }
    s.speed = uniformIn(rng, config_.speed);
    s.velocity.setZero();
    const double r = b.boundingRadius();
    b.placed = false;
    for (int t = 0; t < tries && !b.placed; ++t) {
      if (!drawClearPoint(env, r + kMargin, layout, b.center)) continue;
      const auto too_near = [&](const Eigen::Vector2d& p) {
        return (b.center - p).norm() < config_.start_clearance + r;
      };
      if (std::any_of(keep_clear, keep_clear + count, too_near)) continue;
      b.placed = std::none_of(bodies.begin(), bodies.begin() + k, [&](const Obstacle& o) {
        return o.placed && (o.center - b.center).norm() < o.boundingRadius() + r + kMargin;
      });
    }
    if (!b.placed) {
      ++given_up;
      s.has_waypoint = false;
      continue;
    }
    drawWaypoint(env, static_cast<int>(k), layout, tries);
    if (config_.rule == MoverRule::kStraight && s.has_waypoint) {
      s.velocity = s.speed * (s.waypoint - b.center).normalized();
    }
  }
  return given_up;
}

Eigen::Vector2d MoverSet::socialForce(int env, int k, const EnvLayout& layout,
                                      const Eigen::Vector2d* robots, const std::uint8_t* present,
                                      int count) const {
  const Obstacle& b = bodies_[env][k];
  const State& s = state_[env][k];
  const double r = b.boundingRadius();
  const double a = config_.social_strength, range = config_.social_range;
  const double reach = kForceReach * range;
  Eigen::Vector2d desired = Eigen::Vector2d::Zero();
  if (s.has_waypoint) {
    const Eigen::Vector2d to = s.waypoint - b.center;
    if (to.norm() > 1e-9) desired = s.speed * to.normalized();
  }
  Eigen::Vector2d f = (desired - s.velocity) / config_.relaxation_time;
  const auto push = [&](const Eigen::Vector2d& from, double radius) {
    const Eigen::Vector2d away = b.center - from;
    const double d = away.norm();
    const double gap = d - r - radius;
    if (gap > reach || d < 1e-9) return;
    f += a * std::exp(-gap / range) * away / d;
  };
  for (std::size_t j = 0; j < bodies_[env].size(); ++j) {
    const Obstacle& o = bodies_[env][j];
    if (static_cast<int>(j) != k && o.placed) push(o.center, o.boundingRadius());
  }
  for (int i = 0; config_.avoid_robot && i < count; ++i) {
    if (!present || present[i]) push(robots[i], world_.robotRadius());
  }
  // Each wall and obstacle pushes from its nearest point, as Helbing's walls do; a map's cells
  // push along the gradient of the distance to them.
  const auto push_from = [&](const Obstacle& o) {
    if (!o.placed || (o.center - b.center).norm() - o.boundingRadius() - r > reach) return;
    Eigen::Vector2d normal;
    const double d = outward(o, b.center, normal);
    f += a * std::exp(-(d - r) / range) * normal;
  };
  for (const Obstacle& w : world_.walls()) push_from(w);
  for (const Obstacle& o : layout.obstacles) push_from(o);
  for (const Obstacle& o : world_.worldObstacles()) push_from(o);
  if (world_.hasObstacleCells()) {
    const double c = world_.staticClearance(b.center);
    if (c - r <= reach) {
      const auto at = [&](double dx, double dy) {
        return world_.staticClearance(b.center + Eigen::Vector2d(dx, dy));
      };
      const double h = kGradientStep;
      const Eigen::Vector2d g(at(h, 0) - at(-h, 0), at(0, h) - at(0, -h));
      if (g.norm() > 1e-9) f += a * std::exp(-(c - r) / range) * g.normalized();
    }
  }
  return f;
}

void MoverSet::plan(int env, const EnvLayout& layout, const Eigen::Vector2d* robots,
                    const std::uint8_t* present, int count, double dt) {
  std::vector<Obstacle>& bodies = bodies_[env];
  std::vector<State>& states = state_[env];
  const int n = static_cast<int>(bodies.size());
  for (int k = 0; k < n; ++k) {
    const Obstacle& b = bodies[k];
    State& s = states[k];
    if (!b.placed) continue;
    const double arrived = std::max(0.5 * b.boundingRadius(), s.speed * dt);
    if (!s.has_waypoint || (s.waypoint - b.center).norm() <= arrived) {
      drawWaypoint(env, k, layout, kWaypointTries);
    }
  }
  // Every velocity from the same positions (the order of the movers changes nothing).
  thread_local std::vector<Eigen::Vector2d> next;
  next.resize(n);
  for (int k = 0; k < n; ++k) {
    const Obstacle& b = bodies[k];
    const State& s = states[k];
    next[k] = Eigen::Vector2d::Zero();
    if (!b.placed || !s.has_waypoint) continue;
    const Eigen::Vector2d to = s.waypoint - b.center;
    if (config_.rule == MoverRule::kStraight) {
      next[k] = std::min(s.speed, to.norm() / dt) * to.normalized();
      continue;
    }
    Eigen::Vector2d v = s.velocity + dt * socialForce(env, k, layout, robots, present, count);
    const double top = kMaxSpeedFactor * s.speed;
    if (v.norm() > top) v *= top / v.norm();
    // Never into the world: a step that would take it nearer than its outline stands instead,
    // and it heads elsewhere.
    const Eigen::Vector2d to_be = b.center + dt * v;
    const double r = b.boundingRadius();
    if (!world_.isClear(to_be, r, layout.obstacles) &&
        world_.clearance(to_be, &layout.obstacles) <
            world_.clearance(b.center, &layout.obstacles)) {
      v.setZero();
      states[k].has_waypoint = false;
    }
    next[k] = v;
  }
  for (int k = 0; k < n; ++k) {
    states[k].velocity = next[k];
    Obstacle& b = bodies[k];
    // A cart turns to where it goes.
    if (b.shape == Obstacle::Shape::kBox && next[k].norm() > 1e-6) {
      b.yaw = std::atan2(next[k].y(), next[k].x());
    }
  }
}

void MoverSet::markNear(int env, const Eigen::Vector2d& robot, double dt,
                        std::vector<std::uint8_t>& near) const {
  const std::vector<Obstacle>& bodies = bodies_[env];
  const double margin = std::max(kNearMargin, kNearPerSecond * dt);
  near.resize(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const Obstacle& b = bodies[k];
    const double gap = (b.center - robot).norm() - b.boundingRadius() - world_.robotRadius();
    near[k] = b.placed && gap < state_[env][k].velocity.norm() * dt + margin;
  }
}

void MoverSet::advance(int env, double dt) {
  std::vector<Obstacle>& bodies = bodies_[env];
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (bodies[k].placed) bodies[k].center += dt * state_[env][k].velocity;
  }
}

}  // namespace jetbot_rl
