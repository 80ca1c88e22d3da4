// The surfaces of a Gazebo world's shapes as triangles (for their cut at a height), and its solids
// moved rigidly (a repeated model's copies).
#include "world/solid_surfaces.h"

#include <cmath>
#include <limits>

#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

// Facets of round surfaces (cylinders, spheres) that are not upright.
constexpr int kRoundFacets = 32;

/// Appends the side triangles between consecutive rings (`rings[i][j]`: point j around ring i).
void addRings(const std::vector<std::vector<Eigen::Vector3d>>& rings,
              std::vector<Eigen::Vector3d>& out) {
  for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
    const auto& a = rings[i];
    const auto& b = rings[i + 1];
    for (std::size_t j = 0; j < a.size(); ++j) {
      const std::size_t k = (j + 1) % a.size();
      out.insert(out.end(), {a[j], a[k], b[k], a[j], b[k], b[j]});
    }
  }
}

void addCap(const std::vector<Eigen::Vector3d>& ring, std::vector<Eigen::Vector3d>& out) {
  for (std::size_t j = 1; j + 1 < ring.size(); ++j)
    out.insert(out.end(), {ring[0], ring[j], ring[j + 1]});
}

}  // namespace

/// A box of `size` centred on the origin.
std::vector<Eigen::Vector3d> boxSurface(const Eigen::Vector3d& size) {
  const Eigen::Vector3d h = 0.5 * size;
  std::vector<Eigen::Vector3d> bottom, top;
  for (const auto& [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    bottom.emplace_back(x * h.x(), y * h.y(), -h.z());
    top.emplace_back(x * h.x(), y * h.y(), h.z());
  }
  std::vector<Eigen::Vector3d> out;
  addRings({bottom, top}, out);
  addCap(bottom, out);
  addCap(top, out);
  return out;
}

/// A cylinder along z of `radius` and `length`, centred on the origin, its facets outside the
/// round surface (a cut holds the true cross-section).
std::vector<Eigen::Vector3d> cylinderSurface(double radius, double length) {
  const double r = radius / std::cos(kPi / kRoundFacets);
  std::vector<Eigen::Vector3d> bottom, top;
  for (int j = 0; j < kRoundFacets; ++j) {
    const double a = 2.0 * kPi * j / kRoundFacets;
    bottom.emplace_back(r * std::cos(a), r * std::sin(a), -0.5 * length);
    top.emplace_back(r * std::cos(a), r * std::sin(a), 0.5 * length);
  }
  std::vector<Eigen::Vector3d> out;
  addRings({bottom, top}, out);
  addCap(bottom, out);
  addCap(top, out);
  return out;
}

/// An ellipsoid of semi-axes `radii` centred on `centre`, its facets outside the surface.
std::vector<Eigen::Vector3d> ellipsoidSurface(const Eigen::Vector3d& radii,
                                              const Eigen::Vector3d& centre) {
  const int stacks = kRoundFacets / 2;
  const double grow = 1.0 / (std::cos(kPi / kRoundFacets) * std::cos(kPi / (2 * stacks)));
  std::vector<std::vector<Eigen::Vector3d>> rings;
  for (int i = 0; i <= stacks; ++i) {
    const double polar = kPi * i / stacks;
    std::vector<Eigen::Vector3d> ring;
    for (int j = 0; j < kRoundFacets; ++j) {
      const double a = 2.0 * kPi * j / kRoundFacets;
      const Eigen::Vector3d unit(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a),
                                 -std::cos(polar));
      ring.push_back(centre + grow * radii.cwiseProduct(unit));
    }
    rings.push_back(ring);
  }
  std::vector<Eigen::Vector3d> out;
  addRings(rings, out);
  return out;
}

/// The side walls of a `<polyline>`: its points extruded from z = 0 to `height`.
std::vector<Eigen::Vector3d> polylineSurface(const std::vector<Eigen::Vector2d>& points,
                                             double height) {
  std::vector<Eigen::Vector3d> bottom, top;
  for (const Eigen::Vector2d& p : points) {
    bottom.emplace_back(p.x(), p.y(), 0.0);
    top.emplace_back(p.x(), p.y(), height);
  }
  std::vector<Eigen::Vector3d> out;
  addRings({bottom, top}, out);
  return out;
}

/// Makes `solid` the upright `o` from `bottom` to `top` [m], with its bounds.
void setUpright(WorldSolid& solid, Obstacle o, double bottom, double top) {
  o.height = std::max(0.0, top);
  solid.bottom = bottom;
  solid.top = top;
  solid.bounds.setEmpty();
  if (o.shape == Obstacle::Shape::kCylinder) {
    const Eigen::Vector2d r = Eigen::Vector2d::Constant(o.radius);
    solid.bounds.extend(o.center - r).extend(o.center + r);
  } else {  // the box's corners
    const double c = std::cos(o.yaw), s = std::sin(o.yaw);
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        const Eigen::Vector2d corner(sx * o.half_extents.x(), sy * o.half_extents.y());
        solid.bounds.extend(o.center + Eigen::Vector2d(c * corner.x() - s * corner.y(),
                                                       s * corner.x() + c * corner.y()));
      }
    }
  }
  solid.upright = o;
  solid.triangles.clear();
}

/// Makes `solid` the surface `local` (triangle corners) placed by `pose`, with its extent.
void setSurface(WorldSolid& solid, const std::vector<Eigen::Vector3d>& local,
                const Eigen::Isometry3d& pose) {
  solid.upright.reset();
  solid.triangles.clear();
  solid.bounds.setEmpty();
  solid.bottom = std::numeric_limits<double>::infinity();
  solid.top = -solid.bottom;
  for (const Eigen::Vector3d& p : local) {
    solid.triangles.push_back(pose * p);
    solid.bottom = std::min(solid.bottom, solid.triangles.back().z());
    solid.top = std::max(solid.top, solid.triangles.back().z());
    solid.bounds.extend(solid.triangles.back().head<2>());
  }
}

/// `solid` moved by `move` (in the world frame): an upright one stays exact while `move` keeps
/// its axis vertical, else it becomes its surface.
WorldSolid moved(const WorldSolid& solid, const Eigen::Isometry3d& move) {
  WorldSolid out;
  out.name = solid.name;
  if (!solid.upright) {
    setSurface(out, solid.triangles, move);
    return out;
  }
  const Obstacle& o = *solid.upright;
  const double length = solid.top - solid.bottom;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(o.center.x(), o.center.y(), solid.bottom + 0.5 * length);
  pose.linear() = Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Isometry3d now = move * pose;
  if (std::abs(now.linear()(2, 2)) >= kUprightCos) {
    Obstacle u = o;
    u.center = now.translation().head<2>();
    if (u.shape == Obstacle::Shape::kBox)
      u.yaw = std::atan2(now.linear()(1, 0), now.linear()(0, 0));
    const double mid = now.translation().z();
    setUpright(out, u, mid - 0.5 * length, mid + 0.5 * length);
    return out;
  }
  setSurface(out, uprightSurface(o, length), now);
  return out;
}

std::vector<Eigen::Vector3d> uprightSurface(const Obstacle& o, double length) {
  return o.shape == Obstacle::Shape::kBox
             ? boxSurface(
                   Eigen::Vector3d(2.0 * o.half_extents.x(), 2.0 * o.half_extents.y(), length))
             : cylinderSurface(o.radius, length);
}

}  // namespace jetbot_rl
