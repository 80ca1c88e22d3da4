#include "sensors/seen_spheres.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

Eigen::Vector4d uprightBoundingSphere(const Obstacle& o) {
  const double half = 0.5 * o.height;
  const double across = o.shape == Obstacle::Shape::kCylinder ? o.radius : o.half_extents.norm();
  return {o.center.x(), o.center.y(), half, std::sqrt(across * across + half * half)};
}

void appendBoundingSpheres(const Obstacle& o, std::vector<Eigen::Vector4f>& out) {
  const double across = o.shape == Obstacle::Shape::kCylinder ? o.radius : o.half_extents.norm();
  const int pieces = std::clamp(static_cast<int>(std::ceil(o.height / (2.0 * across))), 1, 4);
  const double half = 0.5 * o.height / pieces;
  const float radius = static_cast<float>(std::sqrt(across * across + half * half));
  for (int k = 0; k < pieces; ++k) {
    out.emplace_back(o.center.x(), o.center.y(), (2 * k + 1) * half, radius);
  }
}

void seenSpheres(const std::vector<Eigen::Vector4f>& spheres, const std::vector<int>* owners,
                 const Eigen::Isometry3d& pose, float far, std::vector<SeenSphere>& out) {
  out.clear();
  const Eigen::Matrix3f to_optical = pose.linear().transpose().cast<float>();
  const Eigen::Vector3f origin = pose.translation().cast<float>();
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const Eigen::Vector4f& s = spheres[k];
    // A little larger than it is, so that rounding never leaves out what a ray meets.
    const float radius = s[3] * (1.0f + 1e-5f) + 1e-5f;
    const Eigen::Vector3f c = to_optical * (s.head<3>() - origin);
    const float distance = c.norm();
    if (c.z() < -radius || distance - radius > far) continue;
    SeenSphere seen;
    seen.owner = owners ? (*owners)[k] : -1;
    if (distance <= radius) {
      seen.towards = Eigen::Vector3f::UnitZ();
      seen.sin_span = 1.0f;
      seen.cos_span = -1.0f;  // a span of pi: any direction
    } else {
      seen.towards = c / distance;
      seen.sin_span = radius / distance;
      seen.cos_span = std::sqrt(1.0f - seen.sin_span * seen.sin_span);
    }
    out.push_back(seen);
  }
}

}  // namespace jetbot_rl
