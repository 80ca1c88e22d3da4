// cutSolids(): a Gazebo world's solids cut by a horizontal plane into an occupancy grid, the way a
// 2D scanner at that height sees them. Conservative: every cell the cross-section touches is
// occupied (its outline traced cell by cell, its inside filled row by row).
#include <algorithm>
#include <cmath>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "planning/grid_walk.h"

namespace jetbot_rl {
namespace {

using Segment = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

class Raster {
 public:
  explicit Raster(OccupancyMap& map)
      : map_(map), origin_(map.origin_x, map.origin_y), res_(map.resolution) {}

  void mark(long x, long y) {
    if (x >= 0 && y >= 0 && x < map_.width && y < map_.height) {
      map_.data[static_cast<std::size_t>(y) * map_.width + x] = 100;
    }
  }

  /// Every cell the segment passes through.
  void trace(const Segment& s) {
    const Eigen::Vector2d a = (s.first - origin_) / res_, b = (s.second - origin_) / res_;
    GridWalk walk(a, b - a, static_cast<long>(std::floor(a.x())),
                  static_cast<long>(std::floor(a.y())));
    const long cells = std::abs(static_cast<long>(std::floor(b.x())) - walk.x) +
                       std::abs(static_cast<long>(std::floor(b.y())) - walk.y);
    mark(walk.x, walk.y);
    for (long n = 0; n < cells; ++n) {
      walk.advance();
      mark(walk.x, walk.y);
    }
  }

  /// The cells whose centre lies inside the closed outline `segments` (even-odd rule).
  void fill(const std::vector<Segment>& segments) {
    Eigen::AlignedBox2d box;
    for (const Segment& s : segments) box.extend(s.first).extend(s.second);
    if (box.isEmpty()) return;
    const long y0 =
        std::max(0L, static_cast<long>(std::floor((box.min().y() - origin_.y()) / res_)));
    const long y1 = std::min<long>(
        map_.height - 1, static_cast<long>(std::floor((box.max().y() - origin_.y()) / res_)));
    std::vector<double> xs;
    for (long y = y0; y <= y1; ++y) {
      const double yc = origin_.y() + (y + 0.5) * res_;
      xs.clear();
      for (const auto& [a, b] : segments) {
        if ((a.y() <= yc) == (b.y() <= yc)) continue;
        xs.push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
      std::sort(xs.begin(), xs.end());
      for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
        const long from = static_cast<long>(std::ceil((xs[i] - origin_.x()) / res_ - 0.5));
        const long to = static_cast<long>(std::floor((xs[i + 1] - origin_.x()) / res_ - 0.5));
        for (long x = std::max(0L, from); x <= std::min<long>(to, map_.width - 1); ++x) mark(x, y);
      }
    }
  }

  /// The cells a circle overlaps.
  void disc(const Eigen::Vector2d& centre, double radius) {
    const Eigen::Vector2d c = (centre - origin_) / res_;
    const double r = radius / res_;
    for (long y = static_cast<long>(std::floor(c.y() - r)); y <= std::floor(c.y() + r); ++y) {
      for (long x = static_cast<long>(std::floor(c.x() - r)); x <= std::floor(c.x() + r); ++x) {
        const Eigen::Vector2d nearest(std::clamp(c.x(), double(x), double(x + 1)),
                                      std::clamp(c.y(), double(y), double(y + 1)));
        if ((nearest - c).squaredNorm() <= r * r) mark(x, y);
      }
    }
  }

 private:
  OccupancyMap& map_;
  Eigen::Vector2d origin_;
  double res_;
};

/// The outline of a solid's triangles cut by z = height (a vertex on the plane counts as above).
std::vector<Segment> cutTriangles(const std::vector<Eigen::Vector3d>& corners, double height) {
  std::vector<Segment> out;
  for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
    Eigen::Vector2d ends[2];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& a = corners[t + e];
      const Eigen::Vector3d& b = corners[t + (e + 1) % 3];
      const double da = a.z() - height, db = b.z() - height;
      if ((da >= 0.0) == (db >= 0.0) || n == 2) continue;
      ends[n++] = (a + (b - a) * (da / (da - db))).head<2>();
    }
    if (n == 2) out.emplace_back(ends[0], ends[1]);
  }
  return out;
}

}  // namespace

bool crossesHeight(const WorldSolid& solid, double height) {
  return solid.bottom <= height && height <= solid.top;
}

Eigen::AlignedBox2d cutArea(const std::vector<WorldSolid>& solids, double height, double resolution,
                            double margin) {
  Eigen::AlignedBox2d area;
  for (const WorldSolid& s : solids) {
    if (crossesHeight(s, height)) area.extend(s.bounds);
  }
  if (area.isEmpty()) return area;
  const Eigen::Vector2d grow = Eigen::Vector2d::Constant(margin);
  const Eigen::Vector2d lo = ((area.min() - grow) / resolution).array().floor() * resolution;
  const Eigen::Vector2d hi = ((area.max() + grow) / resolution).array().ceil() * resolution;
  return Eigen::AlignedBox2d(lo, hi);
}

OccupancyMap cutSolids(const std::vector<WorldSolid>& solids, double height, double resolution,
                       const Eigen::AlignedBox2d& area, SolidKinds which) {
  OccupancyMap map;
  map.resolution = resolution;
  map.origin_x = area.min().x();
  map.origin_y = area.min().y();
  map.width = std::max(1, static_cast<int>(std::lround(area.sizes().x() / resolution)));
  map.height = std::max(1, static_cast<int>(std::lround(area.sizes().y() / resolution)));
  map.data.assign(static_cast<std::size_t>(map.width) * map.height, 0);
  Raster raster(map);
  for (const WorldSolid& s : solids) {
    if (!crossesHeight(s, height)) continue;
    if (which == SolidKinds::kUpright && !s.upright) continue;
    if (which == SolidKinds::kOthers && s.upright) continue;
    std::vector<Segment> outline;
    if (s.upright && s.upright->shape == Obstacle::Shape::kCylinder) {
      raster.disc(s.upright->center, s.upright->radius);
      continue;
    }
    if (s.upright) {
      const Obstacle& o = *s.upright;
      const double c = std::cos(o.yaw), sn = std::sin(o.yaw);
      Eigen::Vector2d corners[4];
      int k = 0;
      for (const auto& [sx, sy] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        const Eigen::Vector2d p(sx * o.half_extents.x(), sy * o.half_extents.y());
        corners[k++] = o.center + Eigen::Vector2d(c * p.x() - sn * p.y(), sn * p.x() + c * p.y());
      }
      for (int i = 0; i < 4; ++i) outline.emplace_back(corners[i], corners[(i + 1) % 4]);
    } else {
      outline = cutTriangles(s.triangles, height);
    }
    for (const Segment& seg : outline) raster.trace(seg);
    raster.fill(outline);
  }
  return map;
}

}  // namespace jetbot_rl
