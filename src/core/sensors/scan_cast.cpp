// castScan(): a scan cast against the world's walls and map and an env's obstacles, exactly, at a
// cost that grows with the beams an obstacle covers rather than with beams x obstacles.
#include <LinearMath/btAabbUtil2.h>
#include <LinearMath/btVector3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "jetbot_rl/numeric.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "planning/grid_walk.h"
#include "sensors/scan_rays.h"

namespace jetbot_rl {
namespace {

/// The unit directions of a scanner's beams in its own frame (cos, sin of each beam's angle),
/// computed once per scanner and thread.
const std::vector<Eigen::Vector2d>& beamDirections(const ScannerSpec& spec) {
  thread_local std::vector<Eigen::Vector2d> directions;
  thread_local double min_angle = 0.0, increment = 0.0;
  const double inc = spec.angleIncrement();
  if (static_cast<int>(directions.size()) != spec.samples || min_angle != spec.min_angle ||
      increment != inc) {
    directions.clear();
    for (int k = 0; k < spec.samples; ++k) {
      const double angle = spec.min_angle + k * inc;
      directions.emplace_back(std::cos(angle), std::sin(angle));
    }
    min_angle = spec.min_angle;
    increment = inc;
  }
  return directions;
}

/// atan2(y, x) [rad] within kAtanError: a window it places, widened by the error, still holds
/// every beam it must (std::atan2 costs as much as testing a few beams).
constexpr double kAtanError = 2e-5;
double roughAtan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double big = std::max(ax, ay);
  if (big == 0.0) return 0.0;
  const double a = std::min(ax, ay) / big, s = a * a;
  // atan on [0, 1], error below 1e-5 rad (Abramowitz and Stegun 4.4.49's degree).
  double r = a * (0.99997726 +
                  s * (-0.33262347 +
                       s * (0.19354346 + s * (-0.11643287 + s * (0.05265332 + s * -0.01172120)))));
  if (ay > ax) r = 0.5 * kPi - r;
  if (x < 0.0) r = kPi - r;
  return y < 0.0 ? -r : r;
}

/// Which beams can hit a shape seen from the sensor: the beams whose direction in the ground
/// plane lies within the angle its bounding circle subtends (a beam outside that angle cannot
/// pass the bounding circle), widened by what a tilt of the scanner's plane can bend a beam's
/// ground-plane direction (less than tilt^2 for tilts below a radian) and by the rounding of
/// the angles. Most small shapes far away fall between two beams: no beam to test.
class BeamWindow {
 public:
  BeamWindow(const ScannerSpec& spec, const Eigen::Matrix3d& basis) : samples_(spec.samples) {
    const double inc = spec.angleIncrement();
    all_ = inc <= 0.0 || basis(2, 2) < 0.5;  // one beam, or a scanner far from level
    if (all_) return;
    per_rad_ = 1.0 / inc;
    turn_ = 2.0 * kPi * per_rad_;
    // Beam angle 0 in the ground plane, and the margin, in beams from the first beam.
    offset_ = (std::atan2(basis(1, 0), basis(0, 0)) + spec.min_angle) * per_rad_;
    margin_ = (4.0 * (1.0 - basis(2, 2)) + 2.0 * kAtanError + 1e-9) * per_rad_ + 1e-9;
  }
  /// Calls f(k) for every beam k that may hit a circle of radius r whose centre lies at `rel`
  /// (ground plane, from the sensor, at distance rho); some beams more than once.
  template <class F>
  void forEachInCircle(const Eigen::Vector2d& rel, double rho, double r, F&& f) const {
    if (rho <= r) return forEachBeam(f);
    // asin(x) <= x asin(0.5) / 0.5 for x <= 0.5 (asin(x) / x grows).
    const double x = r / rho, half = x <= 0.5 ? 1.0472 * x : std::asin(x);
    const double centre = roughAtan2(rel.y(), rel.x());
    forEachBetween(centre - half, centre + half, f);
  }
  /// The same for the angles [from, to] [rad, ground plane, to - from < pi].
  template <class F>
  void forEachBetween(double from, double to, F&& f) const {
    if (all_) return forEachBeam(f);
    const double lo0 = from * per_rad_ - offset_ - margin_, hi0 = to * per_rad_ - offset_ + margin_;
    if (hi0 - lo0 >= turn_) return forEachBeam(f);
    for (double shift : {-turn_, 0.0, turn_}) {
      const double lo = lo0 + shift, hi = hi0 + shift;
      if (hi < 0.0 || lo > samples_ - 1) continue;
      // ceil(lo) and floor(hi) where they are positive: truncation, and no library rounding.
      const int below = static_cast<int>(lo);
      const int first = lo <= 0.0 ? 0 : below + (below < lo);
      const int last = std::min(samples_ - 1, static_cast<int>(hi));
      for (int k = first; k <= last; ++k) f(k);
    }
  }
  template <class F>
  void forEachBeam(F&& f) const {
    for (int k = 0; k < samples_; ++k) f(k);
  }

 private:
  int samples_;
  bool all_ = false;
  double per_rad_ = 0.0;                // beams per radian
  double turn_ = 0.0;                   // beams per turn
  double offset_ = 0.0, margin_ = 0.0;  // [beams]
};

}  // namespace

BoxFrame::BoxFrame(const Eigen::Vector3d& o, const Obstacle& b, double cos_yaw, double sin_yaw)
    : c(cos_yaw), s(sin_yaw) {
  const Eigen::Vector2d rel = o.head<2>() - b.center;
  from = btVector3(static_cast<btScalar>(c * rel.x() + s * rel.y()),
                   static_cast<btScalar>(-s * rel.x() + c * rel.y()), static_cast<btScalar>(o.z()));
  bounds[0] = btVector3(static_cast<btScalar>(-b.half_extents.x()),
                        static_cast<btScalar>(-b.half_extents.y()), 0);
  bounds[1] = btVector3(static_cast<btScalar>(b.half_extents.x()),
                        static_cast<btScalar>(b.half_extents.y()), static_cast<btScalar>(b.height));
}

double rayBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& b, double best) {
  return rayBox(BoxFrame(o, b, std::cos(b.yaw), std::sin(b.yaw)), d, best);
}

double rayBox(const BoxFrame& box, const Eigen::Vector3d& d, double best) {
  const double dx = box.c * d.x() + box.s * d.y(), dy = -box.s * d.x() + box.c * d.y();
  const auto inverse = [](double v) {
    return static_cast<btScalar>(v == 0.0 ? BT_LARGE_FLOAT : 1.0 / v);
  };
  const btVector3 inv(inverse(dx), inverse(dy), inverse(d.z()));
  const unsigned int sign[3] = {inv.x() < 0, inv.y() < 0, inv.z() < 0};
  btScalar t = 0;
  if (!btRayAabb2(box.from, inv, sign, box.bounds, t, 0, static_cast<btScalar>(best))) return best;
  return std::max(0.0, static_cast<double>(t));
}

double rayCylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& cyl,
                   double best) {
  const Eigen::Vector2d rel = o.head<2>() - cyl.center;
  const Eigen::Vector2d d2 = d.head<2>();
  const double r2 = cyl.radius * cyl.radius;
  const auto within = [&](double t) {
    const double z = o.z() + t * d.z();
    return z >= 0.0 && z <= cyl.height;
  };
  const double a = d2.squaredNorm(), b = rel.dot(d2), c = rel.squaredNorm() - r2;
  if (c <= 0.0 && within(0.0)) return 0.0;  // the beam starts inside
  if (a > 0.0) {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double t = (-b - std::sqrt(disc)) / a;
      if (t >= 0.0 && t < best && within(t)) return t;
    }
  }
  if (d.z() < 0.0 && o.z() > cyl.height) {  // through the top
    const double t = (cyl.height - o.z()) / d.z();
    if (t < best && (rel + t * d2).squaredNorm() <= r2) return t;
  }
  return best;
}

double rayMap(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const WorldModel& world,
              double height, double best) {
  const OccupancyMap& map = *world.map();
  const Eigen::Isometry2d to_map = world.mapPose().inverse();
  const double res = map.resolution;
  const Eigen::Vector2d p = to_map * Eigen::Vector2d(o.head<2>()) / res;  // [cells]
  const Eigen::Vector2d v = to_map.linear() * Eigen::Vector2d(d.head<2>()) / res;
  const int w = map.width, h = map.height;
  // Enter the grid: t where the beam reaches [0, w] x [0, h].
  double t = 0.0, t_exit = best;
  for (int axis = 0; axis < 2; ++axis) {
    const double size = axis == 0 ? w : h;
    if (v[axis] == 0.0) {
      if (p[axis] < 0.0 || p[axis] >= size) return best;
      continue;
    }
    double t0 = (0.0 - p[axis]) / v[axis], t1 = (size - p[axis]) / v[axis];
    if (t0 > t1) std::swap(t0, t1);
    t = std::max(t, t0);
    t_exit = std::min(t_exit, t1);
  }
  if (t > t_exit) return best;
  const Eigen::Vector2d start = p + t * v;
  GridWalk walk(p, v, std::min(w - 1, std::max(0, static_cast<int>(std::floor(start.x())))),
                std::min(h - 1, std::max(0, static_cast<int>(std::floor(start.y())))));
  const std::vector<std::uint8_t>& cells = world.obstacleCells();
  while (t < best) {
    if (cells[static_cast<std::size_t>(walk.y) * w + walk.x]) {
      const double z = o.z() + t * d.z();
      if (z >= 0.0 && z <= height) return t;
    }
    t = walk.advance();
    if (walk.x < 0 || walk.x >= w || walk.y < 0 || walk.y >= h) return best;
  }
  return best;
}

void castScan(const ScannerSpec& spec, const WorldModel* world,
              const std::vector<Obstacle>& obstacles, const Eigen::Isometry3d& sensor, Rng& noise,
              float* ranges, const std::vector<Obstacle>* movers) {
  const Eigen::Vector3d o = sensor.translation();
  const Eigen::Matrix3d basis = sensor.linear();
  const double reach = spec.range_max;
  const int n = spec.samples;
  const std::vector<Eigen::Vector2d>& beams = beamDirections(spec);
  thread_local std::vector<Eigen::Vector3d> d;
  thread_local std::vector<double> best;
  thread_local std::vector<std::uint8_t> hit;
  d.resize(n);
  for (int k = 0; k < n; ++k) d[k] = basis * Eigen::Vector3d(beams[k].x(), beams[k].y(), 0.0);
  best.assign(n, reach);
  hit.assign(n, 0);
  const BeamWindow window(spec, basis);
  // Each shape within reach (never the ground, never the robot), against the beams that may hit
  // it; a beam keeps its nearest hit, whatever the order. (The thread's buffers by reference:
  // reaching a thread_local through a shared library's TLS costs a call each time.)
  const std::vector<Eigen::Vector3d>& dir = d;
  std::vector<double>& nearest = best;
  std::vector<std::uint8_t>& hits = hit;
  const auto cast = [&](const Obstacle& ob) {
    const Eigen::Vector2d rel = ob.center - o.head<2>();
    const double rho = rel.norm(), r = ob.boundingRadius();
    if (!ob.placed || rho - r > reach) return;
    const bool box = ob.shape == Obstacle::Shape::kBox;
    double c = 0.0, s = 0.0;        // cos and sin of a box's yaw, once a beam comes near it
    std::optional<BoxFrame> frame;  // the sensor in the box's frame, likewise
    const auto turn = [&] {
      if (frame) return;
      c = std::cos(ob.yaw), s = std::sin(ob.yaw);
      frame.emplace(o, ob, c, s);
    };
    // No hit of this shape is nearer than `near` (its footprint's distance in the ground plane).
    double near = rho - r;
    const auto test = [&](int k) {
      if (nearest[k] < near - 1e-6) return;  // a nearer hit already: none of this shape beats it
      // Cheap rejection: the beam's line misses the bounding circle, or it lies behind.
      const Eigen::Vector3d& dk = dir[k];
      const double along = rel.dot(dk.head<2>());
      const double across2 = rel.squaredNorm() - along * along / dk.head<2>().squaredNorm();
      if (along < -r || across2 > r * r) return;
      if (box) turn();
      const double t = box ? rayBox(*frame, dk, nearest[k]) : rayCylinder(o, dk, ob, nearest[k]);
      if (t < nearest[k]) {
        nearest[k] = t;
        hits[k] = 1;
      }
    };
    if (!box || 2.0 * r < rho) return window.forEachInCircle(rel, rho, r, test);
    // A box large for its distance (an arena wall): the angles of its corners, not its bounding
    // circle's; the sensor in its footprint: every beam.
    turn();
    const Eigen::Vector2d local(c * -rel.x() + s * -rel.y(), -s * -rel.x() + c * -rel.y());
    const Eigen::Vector2d outside(std::max(0.0, std::abs(local.x()) - ob.half_extents.x()),
                                  std::max(0.0, std::abs(local.y()) - ob.half_extents.y()));
    near = outside.norm();
    if (near == 0.0) return window.forEachBeam(test);
    const double centre = roughAtan2(rel.y(), rel.x());
    double from = 0.0, to = 0.0;
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        const Eigen::Vector2d corner(sx * ob.half_extents.x(), sy * ob.half_extents.y());
        const Eigen::Vector2d at =
            rel + Eigen::Vector2d(c * corner.x() - s * corner.y(), s * corner.x() + c * corner.y());
        double a = roughAtan2(at.y(), at.x()) - centre;  // within (-pi, pi) of the centre
        a -= 2.0 * kPi * std::round(a / (2.0 * kPi));
        from = std::min(from, a);
        to = std::max(to, a);
      }
    }
    window.forEachBetween(centre + from, centre + to, test);
  };
  // Near shapes first, so that farther ones find their beams taken and are skipped: the
  // obstacles in rings of reach / kRings by their bounding circle's distance, then the walls.
  constexpr int kRings = 16;
  thread_local std::array<std::vector<const Obstacle*>, kRings> rings;
  std::array<std::vector<const Obstacle*>, kRings>& ring = rings;
  for (auto& r : ring) r.clear();
  const auto sort = [&](const std::vector<Obstacle>& list) {
    for (const Obstacle& ob : list) {
      const double near = (ob.center - o.head<2>()).norm() - ob.boundingRadius();
      if (!ob.placed || near > reach) continue;
      ring[std::clamp(static_cast<int>(near / reach * kRings), 0, kRings - 1)].push_back(&ob);
    }
  };
  sort(obstacles);
  if (movers) sort(*movers);
  if (world) sort(world->worldObstacles());  // a Gazebo world's boxes and cylinders
  for (const auto& r : ring) {
    for (const Obstacle* ob : r) cast(*ob);
  }
  if (world) {
    for (const Obstacle& w : world->walls()) cast(w);
  }
  const bool map = world && world->map() && world->hasObstacleCells();
  const double height = world ? world->config().obstacle_height : 0.0;
  for (int k = 0; k < n; ++k) {
    if (map) {
      const double t = rayMap(o, dir[k], *world, height, nearest[k]);
      if (t < nearest[k]) {
        nearest[k] = t;
        hits[k] = 1;
      }
    }
    float value = kNoReturn;
    if (hits[k]) {
      const double r = spec.noise_std > 0.0 || spec.noise_mean != 0.0
                           ? nearest[k] + spec.noise_mean + spec.noise_std * noise.gaussian()
                           : nearest[k];
      value = r > spec.range_max   ? kNoReturn
              : r < spec.range_min ? kTooClose
                                   : static_cast<float>(r);
    }
    ranges[k] = value;
  }
}

}  // namespace jetbot_rl
