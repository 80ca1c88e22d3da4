#include "world/primitive_uv.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/numeric.h"

namespace jetbot_rl {

namespace {

/// Around the z axis, in [0, 1).
double around(const Eigen::Vector3d& p) { return std::atan2(p.y(), p.x()) / (2.0 * kPi) + 0.5; }

/// A triangle's coordinates around an axis that cross the seam (u from near 1 back to near 0)
/// continued past 1 instead, so that the texture between them is not drawn backwards.
void closeSeam(Eigen::Vector2f* uv) {
  float high = std::max({uv[0].x(), uv[1].x(), uv[2].x()});
  for (int k = 0; k < 3; ++k) {
    if (high - uv[k].x() > 0.5f) uv[k].x() += 1.0f;
  }
}

}  // namespace

std::vector<Eigen::Vector2f> primitiveUv(UvShape shape, const Eigen::Vector3d& size,
                                         const std::vector<Eigen::Vector3d>& local) {
  std::vector<Eigen::Vector2f> uv(local.size());
  for (std::size_t t = 0; t + 2 < local.size(); t += 3) {
    const Eigen::Vector3d* c = &local[t];
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
    Eigen::Vector2f* out = &uv[t];
    switch (shape) {
      case UvShape::kBox: {
        int axis = 0;
        n.cwiseAbs().maxCoeff(&axis);
        // A side face: from its left to its right as seen from outside, and up; the top and
        // bottom: along x and y. The face's side of the box is where its corners lie.
        const double side = (c[0] + c[1] + c[2])[axis] < 0.0 ? -1.0 : 1.0;
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d p = c[k].cwiseQuotient(size);
          out[k] = axis == 0   ? Eigen::Vector2f(side * p.y() + 0.5, p.z() + 0.5)
                   : axis == 1 ? Eigen::Vector2f(-side * p.x() + 0.5, p.z() + 0.5)
                               : Eigen::Vector2f(p.x() + 0.5, p.y() + 0.5);
        }
        break;
      }
      case UvShape::kCylinder: {
        const double r = size.x(), length = size.y();
        const bool cap = std::abs(n.z()) > 0.9 * n.norm();
        for (int k = 0; k < 3; ++k) {
          out[k] = cap ? Eigen::Vector2f(c[k].x() / (2 * r) + 0.5, c[k].y() / (2 * r) + 0.5)
                       : Eigen::Vector2f(around(c[k]), c[k].z() / length + 0.5);
        }
        if (!cap) closeSeam(out);
        break;
      }
      case UvShape::kSphere: {
        const double r = size.x();
        for (int k = 0; k < 3; ++k) {
          out[k] = Eigen::Vector2f(around(c[k]),
                                   1.0 - std::acos(std::clamp(c[k].z() / r, -1.0, 1.0)) / kPi);
        }
        closeSeam(out);
        break;
      }
    }
  }
  return uv;
}

}  // namespace jetbot_rl
