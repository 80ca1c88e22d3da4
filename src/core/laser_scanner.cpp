#include "jetbot_rl/laser_scanner.h"

#include <LinearMath/btAabbUtil2.h>
#include <LinearMath/btVector3.h>

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Distance along the unit ray (o, d) to the box `b` (its frame: yaw about z at its centre,
/// from the ground up to its height), if it is below `best`. Bullet's exact ray-AABB test in
/// the box's frame.
double rayBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Obstacle& b, double best) {
  const double c = std::cos(b.yaw), s = std::sin(b.yaw);
  const Eigen::Vector2d rel = o.head<2>() - b.center;
  const btVector3 from(static_cast<btScalar>(c * rel.x() + s * rel.y()),
                       static_cast<btScalar>(-s * rel.x() + c * rel.y()),
                       static_cast<btScalar>(o.z()));
  const double dx = c * d.x() + s * d.y(), dy = -s * d.x() + c * d.y();
  const auto inverse = [](double v) {
    return static_cast<btScalar>(v == 0.0 ? BT_LARGE_FLOAT : 1.0 / v);
  };
  const btVector3 inv(inverse(dx), inverse(dy), inverse(d.z()));
  const unsigned int sign[3] = {inv.x() < 0, inv.y() < 0, inv.z() < 0};
  const btVector3 bounds[2] = {
      btVector3(static_cast<btScalar>(-b.half_extents.x()),
                static_cast<btScalar>(-b.half_extents.y()), 0),
      btVector3(static_cast<btScalar>(b.half_extents.x()),
                static_cast<btScalar>(b.half_extents.y()), static_cast<btScalar>(b.height))};
  btScalar t = 0;
  if (!btRayAabb2(from, inv, sign, bounds, t, 0, static_cast<btScalar>(best))) return best;
  return std::max(0.0, static_cast<double>(t));
}

/// The same for a vertical cylinder: its side, or its top for a beam from above.
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

/// The same for the map's obstacle cells (prisms up to `height`): a grid traversal in the map
/// frame (Amanatides and Woo), the distance where the beam enters the first obstacle cell.
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
  int x = std::min(w - 1, std::max(0, static_cast<int>(std::floor(start.x()))));
  int y = std::min(h - 1, std::max(0, static_cast<int>(std::floor(start.y()))));
  const int step_x = v.x() > 0 ? 1 : -1, step_y = v.y() > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double delta_x = v.x() != 0.0 ? std::abs(1.0 / v.x()) : inf;
  const double delta_y = v.y() != 0.0 ? std::abs(1.0 / v.y()) : inf;
  double next_x = v.x() != 0.0 ? ((x + (step_x > 0 ? 1 : 0)) - p.x()) / v.x() : inf;
  double next_y = v.y() != 0.0 ? ((y + (step_y > 0 ? 1 : 0)) - p.y()) / v.y() : inf;
  const std::vector<std::uint8_t>& cells = world.obstacleCells();
  while (t < best) {
    if (cells[static_cast<std::size_t>(y) * w + x]) {
      const double z = o.z() + t * d.z();
      if (z >= 0.0 && z <= height) return t;
    }
    if (next_x < next_y) {
      t = next_x;
      next_x += delta_x;
      x += step_x;
      if (x < 0 || x >= w) return best;
    } else {
      t = next_y;
      next_y += delta_y;
      y += step_y;
      if (y < 0 || y >= h) return best;
    }
  }
  return best;
}

template <typename T>
std::string text(T v) {
  std::ostringstream s;
  writeValue(s, v);
  return s.str();
}

}  // namespace

void checkFieldRules(const ScannerConfig& c) {
  for (const auto& [name, v] :
       {std::make_pair("scan/angles", &c.angles), std::make_pair("scan/range", &c.range)}) {
    if (!v->empty() && v->size() != 2) throwInvalid(name, listText(*v), "must be [min, max] or []");
  }
}

std::optional<ScannerSpec> resolveScanner(const ScannerConfig& config, const RobotModel& robot,
                                          double control_dt) {
  validateConfig(config);
  if (!config.enabled) return std::nullopt;
  const auto& ray = robot.gazebo().ray;
  ScannerSpec spec;
  spec.link = config.link.empty() ? (ray ? ray->link : "") : config.link;
  spec.link_from = config.link.empty() ? "Gazebo" : "scan/link";
  if (spec.link.empty()) return std::nullopt;
  Eigen::Isometry3d offset;
  if (!robot.findLink(spec.link, spec.body, offset)) {
    throwInvalid("scan/link", "'" + spec.link + "'", "is not a link of the robot description");
  }
  // The Gazebo block gives the defaults of the scanner on its own link.
  const GazeboRaySensor* g = ray && ray->link == spec.link ? &*ray : nullptr;
  const std::string gazebo = g ? " (from the Gazebo ray sensor '" + g->name + "' of link '" +
                                     g->link + "'; set the parameter to override it)"
                               : "";
  spec.pose_in_body = offset * (g ? g->pose : Eigen::Isometry3d::Identity());

  const auto pick = [&](bool set, const char* name, bool from_gazebo) {
    return set ? std::string(name) : from_gazebo ? std::string("Gazebo") : std::string("default");
  };
  spec.samples = config.samples > 0 ? config.samples : g ? g->samples : 360;
  spec.samples_from = pick(config.samples > 0, "scan/samples", g);
  if (spec.samples < 1 || spec.samples > 100000) {
    throwInvalid("scan/samples", spec.samples,
                 "must be in [1, 100000]" + (config.samples > 0 ? std::string() : gazebo));
  }
  // A [min, max] pair: the parameter's, else the Gazebo block's, else the default.
  const auto pair = [g](const std::vector<double>& set, double gazebo_min, double gazebo_max,
                        double default_min, double default_max, double& min, double& max) {
    min = set.size() == 2 ? set[0] : g ? gazebo_min : default_min;
    max = set.size() == 2 ? set[1] : g ? gazebo_max : default_max;
  };
  pair(config.angles, g ? g->min_angle : 0.0, g ? g->max_angle : 0.0, -kPi,
       kPi - 2.0 * kPi / spec.samples, spec.min_angle, spec.max_angle);
  spec.angles_from = pick(config.angles.size() == 2, "scan/angles", g);
  const bool angles_ok =
      std::isfinite(spec.min_angle) && std::isfinite(spec.max_angle) &&
      (spec.samples == 1 ? spec.min_angle <= spec.max_angle : spec.min_angle < spec.max_angle);
  if (!angles_ok) {
    throwInvalid(
        "scan/angles", "[" + text(spec.min_angle) + ", " + text(spec.max_angle) + "]",
        "must be [min, max] with min < max" + (config.angles.size() == 2 ? std::string() : gazebo));
  }
  pair(config.range, g ? g->range_min : 0.0, g ? g->range_max : 0.0, 0.12, 3.5, spec.range_min,
       spec.range_max);
  spec.range_from = pick(config.range.size() == 2, "scan/range", g);
  if (!(spec.range_min >= 0.0 && spec.range_min < spec.range_max &&
        std::isfinite(spec.range_max))) {
    throwInvalid("scan/range", "[" + text(spec.range_min) + ", " + text(spec.range_max) + "]",
                 "must be [min, max] with 0 <= min < max, finite" +
                     (config.range.size() == 2 ? std::string() : gazebo));
  }
  if (config.noise_std >= 0.0) {
    spec.noise_std = config.noise_std;
  } else if (g) {
    spec.noise_mean = g->noise_mean;
    spec.noise_std = g->noise_stddev;
  }
  spec.noise_from = pick(config.noise_std >= 0.0, "scan/noise_std", g);
  if (!(spec.noise_std >= 0.0) || !std::isfinite(spec.noise_std) ||
      !std::isfinite(spec.noise_mean)) {
    throwInvalid("scan/noise_std", spec.noise_std, "must be >= 0, finite" + gazebo);
  }
  if (config.update_every > 0) {
    spec.update_every = config.update_every;
  } else if (g && g->update_rate > 0.0) {
    if (!std::isfinite(g->update_rate)) {
      throwInvalid("scan/update_every", g->update_rate, "the update rate must be finite" + gazebo);
    }
    spec.update_every =
        std::max(1, static_cast<int>(std::lround(1.0 / (g->update_rate * control_dt))));
  }
  spec.update_from = pick(config.update_every > 0, "scan/update_every", g && g->update_rate > 0);
  return spec;
}

std::string describeScanner(const ScannerSpec& s) {
  std::ostringstream out;
  out << "laser scanner on link '" << s.link << "' (" << s.link_from << "): " << s.samples
      << " beams (" << s.samples_from << ") over [" << text(s.min_angle) << ", "
      << text(s.max_angle) << "] rad (" << s.angles_from << "), range [" << text(s.range_min)
      << ", " << text(s.range_max) << "] m (" << s.range_from << "), noise mean "
      << text(s.noise_mean) << " std " << text(s.noise_std) << " m (" << s.noise_from << "), every "
      << s.update_every << " control steps (" << s.update_from << ")";
  return out.str();
}

void castScan(const ScannerSpec& spec, const WorldModel* world,
              const std::vector<Obstacle>& obstacles, const Eigen::Isometry3d& sensor, Rng& noise,
              float* ranges) {
  const Eigen::Vector3d o = sensor.translation();
  const Eigen::Matrix3d basis = sensor.linear();
  const double reach = spec.range_max;
  // What a beam may hit: the walls and placed obstacles within reach (never the ground, never the
  // robot), and the map.
  thread_local std::vector<const Obstacle*> near;
  near.clear();
  const auto consider = [&](const Obstacle& ob) {
    if (ob.placed && (ob.center - o.head<2>()).norm() - ob.boundingRadius() <= reach) {
      near.push_back(&ob);
    }
  };
  if (world) {
    for (const Obstacle& w : world->walls()) consider(w);
  }
  for (const Obstacle& ob : obstacles) consider(ob);
  const bool map = world && world->map();
  const double height = world ? world->config().obstacle_height : 0.0;
  const double increment = spec.angleIncrement();
  for (int k = 0; k < spec.samples; ++k) {
    const double angle = spec.min_angle + k * increment;
    const Eigen::Vector3d d = basis * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    double best = reach;
    bool hit = false;
    for (const Obstacle* ob : near) {
      // Cheap rejection: the beam's line misses the bounding circle, or it lies behind.
      const Eigen::Vector2d rel = ob->center - o.head<2>();
      const double along = rel.dot(d.head<2>()), r = ob->boundingRadius();
      const double across2 = rel.squaredNorm() - along * along / d.head<2>().squaredNorm();
      if (along < -r || across2 > r * r) continue;
      const double t = ob->shape == Obstacle::Shape::kBox ? rayBox(o, d, *ob, best)
                                                          : rayCylinder(o, d, *ob, best);
      if (t < best) {
        best = t;
        hit = true;
      }
    }
    if (map) {
      const double t = rayMap(o, d, *world, height, best);
      if (t < best) {
        best = t;
        hit = true;
      }
    }
    float value = kNoReturn;
    if (hit) {
      const double r = spec.noise_std > 0.0 || spec.noise_mean != 0.0
                           ? best + spec.noise_mean + spec.noise_std * noise.gaussian()
                           : best;
      value = r > spec.range_max   ? kNoReturn
              : r < spec.range_min ? kTooClose
                                   : static_cast<float>(r);
    }
    ranges[k] = value;
  }
}

}  // namespace jetbot_rl
