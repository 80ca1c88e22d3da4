#include "jetbot_rl/sensors/camera_model.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

/// The distortion and its Jacobian at normalised point `p`.
struct Distorted {
  Eigen::Vector2d value;
  Eigen::Matrix2d jacobian;
};

Distorted distortWithJacobian(const CameraIntrinsics& c, const Eigen::Vector2d& p) {
  const double x = p.x(), y = p.y(), r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (c.k1 + r2 * (c.k2 + r2 * c.k3));
  const double dradial_dr2 = c.k1 + r2 * (2.0 * c.k2 + 3.0 * r2 * c.k3);
  const double drdx = 2.0 * x * dradial_dr2, drdy = 2.0 * y * dradial_dr2;
  Distorted d;
  d.value = {x * radial + 2.0 * c.p1 * x * y + c.p2 * (r2 + 2.0 * x * x),
             y * radial + c.p1 * (r2 + 2.0 * y * y) + 2.0 * c.p2 * x * y};
  d.jacobian << radial + x * drdx + 2.0 * c.p1 * y + 6.0 * c.p2 * x,
      x * drdy + 2.0 * c.p1 * x + 2.0 * c.p2 * y, y * drdx + 2.0 * c.p1 * x + 2.0 * c.p2 * y,
      radial + y * drdy + 6.0 * c.p1 * y + 2.0 * c.p2 * x;
  return d;
}

/// The normalised point that distortWithJacobian() takes to `target` (Newton's method from
/// `start`); none when it does not converge.
std::optional<Eigen::Vector2d> invertFrom(const CameraIntrinsics& c, const Eigen::Vector2d& target,
                                          Eigen::Vector2d p) {
  for (int i = 0; i < 50; ++i) {
    const Distorted d = distortWithJacobian(c, p);
    const Eigen::Vector2d error = d.value - target;
    if (error.squaredNorm() < 1e-26) return p;
    if (!(std::abs(d.jacobian.determinant()) > 1e-12)) return std::nullopt;
    p -= d.jacobian.inverse() * error;
    if (!p.allFinite()) return std::nullopt;
  }
  const Eigen::Vector2d error = distortWithJacobian(c, p).value - target;
  return error.squaredNorm() < 1e-20 ? std::optional<Eigen::Vector2d>(p) : std::nullopt;
}

/// invertFrom() from `target`, else by continuation: the targets from 0 out to `target`, each
/// solved from the last (Newton alone can leave the basin where the distortion is strong).
std::optional<Eigen::Vector2d> invert(const CameraIntrinsics& c, const Eigen::Vector2d& target) {
  if (std::optional<Eigen::Vector2d> p = invertFrom(c, target, target)) return p;
  constexpr int kSteps = 32;
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int i = 1; i <= kSteps; ++i) {
    const std::optional<Eigen::Vector2d> next = invertFrom(c, target * i / kSteps, p);
    if (!next) return std::nullopt;
    p = *next;
  }
  return p;
}

bool hasDistortion(const CameraIntrinsics& c) {
  return c.k1 != 0.0 || c.k2 != 0.0 || c.k3 != 0.0 || c.p1 != 0.0 || c.p2 != 0.0;
}

}  // namespace

void validateIntrinsics(const CameraIntrinsics& c, const std::string& prefix) {
  if (c.width < 1 || c.width > kMaxImageSide) {
    throwInvalid(prefix + "width", c.width, "must be in [1, 4096] px");
  }
  if (c.height < 1 || c.height > kMaxImageSide) {
    throwInvalid(prefix + "height", c.height, "must be in [1, 4096] px");
  }
  if (!(c.horizontal_fov > 0.0 && c.horizontal_fov < kPi)) {
    throwInvalid(prefix + "horizontal_fov", c.horizontal_fov,
                 "must be in (0, pi) rad (a pinhole sees less than half the sphere)");
  }
  if (!(c.near > 0.0 && std::isfinite(c.near))) {
    throwInvalid(prefix + "clip/near", c.near, "must be > 0 m");
  }
  if (!(c.far > c.near && std::isfinite(c.far))) {
    throwInvalid(prefix + "clip/far", c.far, "must be finite and > clip/near");
  }
  for (const auto& [name, k] : {std::pair<const char*, double>{"k1", c.k1},
                                {"k2", c.k2},
                                {"k3", c.k3},
                                {"p1", c.p1},
                                {"p2", c.p2}}) {
    if (!std::isfinite(k)) throwInvalid(prefix + "distortion/" + name, k, "must be finite");
  }
  if (!hasDistortion(c)) return;
  // Every pixel must have one ray: the distortion reaches each corner of the image from a point
  // of the undistorted plane, and is one to one (its Jacobian positive) on the way out to it.
  const double f = c.width / 2.0 / std::tan(c.horizontal_fov / 2.0);
  const Eigen::Vector2d corner((c.width - 1) / 2.0 / f, (c.height - 1) / 2.0 / f);
  const std::string value = "(k1 " + std::to_string(c.k1) + ", k2 " + std::to_string(c.k2) +
                            ", k3 " + std::to_string(c.k3) + ", p1 " + std::to_string(c.p1) +
                            ", p2 " + std::to_string(c.p2) + ")";
  constexpr int kSteps = 64;
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) {
      const Eigen::Vector2d target = corner.cwiseProduct(Eigen::Vector2d(sx, sy));
      const std::optional<Eigen::Vector2d> source = invert(c, target);
      if (!source) {
        throwInvalid(prefix + "distortion", value,
                     "maps no ray to the image's corners (the lens's field ends inside the "
                     "image): a wider horizontal_fov's corners or a milder distortion");
      }
      for (int i = 1; i <= kSteps; ++i) {
        if (distortWithJacobian(c, *source * i / kSteps).jacobian.determinant() <= 0.0) {
          throwInvalid(prefix + "distortion", value,
                       "folds the image before its corners (a pixel would have two rays)");
        }
      }
    }
  }
}

CameraModel::CameraModel(const CameraIntrinsics& intrinsics, const std::string& prefix)
    : intrinsics_(intrinsics) {
  validateIntrinsics(intrinsics_, prefix);
  f_ = intrinsics_.width / 2.0 / std::tan(intrinsics_.horizontal_fov / 2.0);
  cx_ = (intrinsics_.width - 1) / 2.0;
  cy_ = (intrinsics_.height - 1) / 2.0;
  distorted_ = hasDistortion(intrinsics_);
  pixel_rays_.reserve(static_cast<std::size_t>(width()) * height());
  for (int v = 0; v < height(); ++v) {
    for (int u = 0; u < width(); ++u) {
      pixel_rays_.push_back(ray(u, v).cast<float>());
      ray_reach_ = ray_reach_.cwiseMax(pixel_rays_.back().head<2>().cwiseAbs());
    }
  }
  for (int ty = 0; ty < height(); ty += kTileSide) {
    for (int tx = 0; tx < width(); tx += kTileSide) {
      TileRays tile;
      for (int k = 0; k < TileRays::kLanes; ++k) {
        const int x = tx + k % kTileSide, y = ty + k / kTileSide;
        const bool valid = x < width() && y < height();
        const Eigen::Vector3f r = valid ? pixel_rays_[static_cast<std::size_t>(y) * width() + x]
                                        : Eigen::Vector3f::UnitZ();
        tile.x[k] = r.x();
        tile.y[k] = r.y();
        tile.z[k] = r.z();
        tile.valid[k] = valid ? -1 : 0;
      }
      tile_rays_.push_back(tile);
    }
  }
  tile_cones_ = blockCones(kTileSide);
  group_cones_ = blockCones(kTileSide * kGroupSide);
}

std::vector<TileCone> CameraModel::blockCones(int side) const {
  // [rad]: the cones a little wider than their rays, so that rounding never leaves one out.
  constexpr double kMargin = 1e-5;
  std::vector<TileCone> cones;
  for (int by = 0; by < height(); by += side) {
    for (int bx = 0; bx < width(); bx += side) {
      std::vector<Eigen::Vector3d> unit;
      for (int y = by; y < std::min(height(), by + side); ++y) {
        for (int x = bx; x < std::min(width(), bx + side); ++x) {
          unit.push_back(
              pixel_rays_[static_cast<std::size_t>(y) * width() + x].cast<double>().normalized());
        }
      }
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& u : unit) axis += u;
      axis.normalize();
      double half = 0.0;
      for (const Eigen::Vector3d& u : unit) {
        half = std::max(half, std::atan2(axis.cross(u).norm(), axis.dot(u)));
      }
      half += kMargin;
      TileCone cone;
      cone.everything = half >= 0.5 * kPi;  // nearly a half-space: no use testing against it
      cone.axis = axis.cast<float>();
      cone.cos_half = static_cast<float>(std::cos(half));
      cone.sin_half = static_cast<float>(std::sin(half));
      cones.push_back(cone);
    }
  }
  return cones;
}

Eigen::Vector2d CameraModel::distort(const Eigen::Vector2d& normalised) const {
  if (!distorted_) return normalised;
  return distortWithJacobian(intrinsics_, normalised).value;
}

Eigen::Vector2d CameraModel::undistort(const Eigen::Vector2d& distorted) const {
  if (!distorted_) return distorted;
  // Within the image validateIntrinsics() found an inverse; beyond it, the nearest Newton gives.
  const std::optional<Eigen::Vector2d> p = invert(intrinsics_, distorted);
  return p ? *p : distorted;
}

std::optional<Eigen::Vector2d> CameraModel::project(const Eigen::Vector3d& point) const {
  if (!(point.z() > 0.0)) return std::nullopt;
  const Eigen::Vector2d d = distort(point.head<2>() / point.z());
  return Eigen::Vector2d(f_ * d.x() + cx_, f_ * d.y() + cy_);
}

Eigen::Vector3d CameraModel::ray(double u, double v) const {
  const Eigen::Vector2d p = undistort(Eigen::Vector2d((u - cx_) / f_, (v - cy_) / f_));
  return Eigen::Vector3d(p.x(), p.y(), 1.0);
}

ViewCone::ViewCone(const CameraModel& model, const Eigen::Isometry3d& pose)
    : to_optical_(pose.inverse()), far_(model.intrinsics().far) {
  // A side plane through the widest ray x = +-reach (z = 1), its normal pointing out of the cone;
  // a little wider than the rays, so that rounding never leaves out what a ray meets.
  const Eigen::Vector2d reach =
      model.rayReach().cast<double>() * (1.0 + 1e-6) + Eigen::Vector2d::Constant(1e-6);
  sides_ = {Eigen::Vector3d(1.0, 0.0, -reach.x()).normalized(),
            Eigen::Vector3d(-1.0, 0.0, -reach.x()).normalized(),
            Eigen::Vector3d(0.0, 1.0, -reach.y()).normalized(),
            Eigen::Vector3d(0.0, -1.0, -reach.y()).normalized()};
}

bool ViewCone::mayMeet(const Eigen::Vector3d& centre, double radius) const {
  const Eigen::Vector3d c = to_optical_ * centre;
  if (c.z() < -radius || c.z() > far_ + radius) return false;  // behind, or beyond the far clip
  for (const Eigen::Vector3d& n : sides_) {
    if (n.dot(c) > radius) return false;
  }
  return true;
}

}  // namespace jetbot_rl
