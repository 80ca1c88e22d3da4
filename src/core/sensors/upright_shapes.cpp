#include "jetbot_rl/sensors/upright_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {
namespace {

/// Keeps hit `t` with normal `n` in lane `k` of `hits` when it is nearer than what it holds.
inline void keep(UprightHits& hits, int k, float t, int index, float nx, float ny, float nz) {
  if (!(t > 0.0f && t < hits.t[k])) return;
  hits.t[k] = t;
  hits.shape[k] = index;
  hits.normal_x[k] = nx;
  hits.normal_y[k] = ny;
  hits.normal_z[k] = nz;
}

void intersectCylinder(const UprightShape& s, int index, const PacketRays& rays, const int* valid,
                       UprightHits& hits) {
  const float r = s.half.x(), r2 = r * r;
  for (int k = 0; k < kPacketLanes; ++k) {
    if (!valid[k]) continue;
    const float px = rays.org_x[k] - s.centre.x(), py = rays.org_y[k] - s.centre.y();
    const float dx = rays.dir_x[k], dy = rays.dir_y[k], dz = rays.dir_z[k], oz = rays.org_z[k];
    // The round side: |p + t d|^2 = r^2 in the ground plane, between the ground and the top.
    const float a = dx * dx + dy * dy, b = px * dx + py * dy, c = px * px + py * py - r2;
    const float disc = b * b - a * c;
    if (a > 0.0f && disc >= 0.0f) {
      const float root = std::sqrt(disc);
      // From outside the nearer crossing; from inside (c < 0) the way out.
      const float t = c > 0.0f ? (-b - root) / a : (-b + root) / a;
      const float z = oz + t * dz;
      if (z >= 0.0f && z <= s.height) {
        keep(hits, k, t, index, (px + t * dx) / r, (py + t * dy) / r, 0.0f);
      }
    }
    // The top (the bottom lies on the ground, which the renderer draws).
    if (dz != 0.0f) {
      const float t = (s.height - oz) / dz;
      const float x = px + t * dx, y = py + t * dy;
      if (x * x + y * y <= r2) keep(hits, k, t, index, 0.0f, 0.0f, 1.0f);
    }
  }
}

/// The distances at which a ray at `o` along `d` enters and leaves the slab |x| <= half (NaN-free:
/// a ray along the slab is inside it everywhere or nowhere).
inline void slab(float o, float d, float half, float& enter, float& leave) {
  if (d == 0.0f) {
    const bool inside = std::abs(o) <= half;
    enter =
        inside ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
    leave =
        inside ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    return;
  }
  const float t1 = (-half - o) / d, t2 = (half - o) / d;
  enter = std::min(t1, t2);
  leave = std::max(t1, t2);
}

void intersectBox(const UprightShape& s, int index, const PacketRays& rays, const int* valid,
                  UprightHits& hits) {
  const float c = s.cos_yaw, sn = s.sin_yaw, half_z = 0.5f * s.height;
  for (int k = 0; k < kPacketLanes; ++k) {
    if (!valid[k]) continue;
    // The ray in the box's frame: rotated by -yaw about its centre, z from its middle.
    const float px = rays.org_x[k] - s.centre.x(), py = rays.org_y[k] - s.centre.y();
    const float lx = c * px + sn * py, ly = -sn * px + c * py, lz = rays.org_z[k] - half_z;
    const float dx = c * rays.dir_x[k] + sn * rays.dir_y[k];
    const float dy = -sn * rays.dir_x[k] + c * rays.dir_y[k], dz = rays.dir_z[k];
    float enter[3], leave[3];
    slab(lx, dx, s.half.x(), enter[0], leave[0]);
    slab(ly, dy, s.half.y(), enter[1], leave[1]);
    slab(lz, dz, half_z, enter[2], leave[2]);
    const int in_axis = static_cast<int>(std::max_element(enter, enter + 3) - enter);
    const int out_axis = static_cast<int>(std::min_element(leave, leave + 3) - leave);
    const float t_in = enter[in_axis], t_out = leave[out_axis];
    if (!(t_in <= t_out) || !(t_out > 0.0f)) continue;
    // From outside the face it enters by; from inside the face it leaves by.
    const bool outside = t_in > 0.0f;
    const int axis = outside ? in_axis : out_axis;
    const float t = outside ? t_in : t_out;
    const float along[3] = {dx, dy, dz};
    const float sign = (along[axis] > 0.0f) == outside ? -1.0f : 1.0f;
    float n[3] = {0.0f, 0.0f, 0.0f};
    n[axis] = sign;
    keep(hits, k, t, index, c * n[0] - sn * n[1], sn * n[0] + c * n[1], n[2]);
  }
}

}  // namespace

UprightShape UprightShape::of(const Obstacle& o) {
  UprightShape s;
  s.cylinder = o.shape == Obstacle::Shape::kCylinder;
  s.centre = o.center.cast<float>();
  s.cos_yaw = static_cast<float>(std::cos(o.yaw));
  s.sin_yaw = static_cast<float>(std::sin(o.yaw));
  s.half = s.cylinder ? Eigen::Vector2f(Eigen::Vector2f::Constant(static_cast<float>(o.radius)))
                      : Eigen::Vector2f(o.half_extents.cast<float>());
  s.height = static_cast<float>(o.height);
  return s;
}

void intersectUpright(const UprightShape& shape, int index, const PacketRays& rays,
                      const int* valid, UprightHits& hits) {
  if (shape.cylinder) {
    intersectCylinder(shape, index, rays, valid, hits);
  } else {
    intersectBox(shape, index, rays, valid, hits);
  }
}

}  // namespace jetbot_rl
