#pragma once

// A camera's projection as Gazebo's camera sensors define it: a pinhole of horizontal field of
// view `horizontal_fov` over `width` x `height` square pixels, with the Brown-Conrady distortion
// of the sensor block (k1 k2 k3 radial, p1 p2 tangential, on normalised image coordinates), in
// the optical frame of REP 103 (z forward, x right, y down). Pixel (0, 0)'s centre is at (0, 0):
// the principal point is the image's centre ((width - 1) / 2, (height - 1) / 2).

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace jetbot_rl {

/// What makes a camera's image geometry: the block's <horizontal_fov>, <image>, <clip> and
/// <distortion>.
struct CameraIntrinsics {
  int width = 64;                       ///< [px]
  int height = 64;                      ///< [px]
  double horizontal_fov = 1.047;        ///< [rad], in (0, pi)
  double near = 0.05;                   ///< Nearest depth measured (clip near) [m]
  double far = 10.0;                    ///< Farthest depth measured (clip far) [m]
  double k1 = 0.0, k2 = 0.0, k3 = 0.0;  ///< Radial distortion.
  double p1 = 0.0, p2 = 0.0;            ///< Tangential distortion.
};

/// The largest image side accepted [px].
constexpr int kMaxImageSide = 4096;
/// The side of the square tiles of pixels a renderer traces together [px].
constexpr int kTileSide = 4;
/// The side of the square groups of tiles a renderer culls together [tiles].
constexpr int kGroupSide = 4;

/// The pixel rays of one tile: a cone about `axis` (unit, optical frame) holding each of them.
struct TileCone {
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();
  float cos_half = 1.0f, sin_half = 0.0f;  ///< Of the cone's half-angle (a little widened).
  bool everything = false;  ///< A half-angle of pi / 2 or more: a cone of every direction.
};

/// The pixel rays of one tile, lane k = (k % kTileSide, k / kTileSide) from its top left corner,
/// each coordinate in a row (for loops the compiler vectorises). A lane beyond the image's edge
/// is invalid (its ray: the optical axis).
struct TileRays {
  static constexpr int kLanes = kTileSide * kTileSide;
  alignas(64) float x[kLanes];
  alignas(64) float y[kLanes];
  alignas(64) float z[kLanes];
  alignas(64) int valid[kLanes];  ///< -1: a pixel, 0: none
};

/// ConfigError naming the field (`prefix` + "width", ...) and value when `intrinsics` is no
/// camera: a side outside [1, kMaxImageSide], a field of view outside (0, pi), near <= 0,
/// near >= far, a distortion that folds the image (not monotonic out to its corners).
void validateIntrinsics(const CameraIntrinsics& intrinsics, const std::string& prefix);

/**
 * The projection of a camera (validated intrinsics): points to pixels and pixels to rays. The
 * focal length is Gazebo's: fx = fy = width / 2 / tan(horizontal_fov / 2) [px].
 */
class CameraModel {
 public:
  /// ConfigError as validateIntrinsics() with `prefix`.
  explicit CameraModel(const CameraIntrinsics& intrinsics, const std::string& prefix = "camera/");

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  int width() const { return intrinsics_.width; }
  int height() const { return intrinsics_.height; }
  double fx() const { return f_; }   ///< [px]
  double fy() const { return f_; }   ///< [px]
  double cx() const { return cx_; }  ///< [px]
  double cy() const { return cy_; }  ///< [px]
  bool distorted() const { return distorted_; }

  /// Where a point of the optical frame [m] lands [px], or none behind the camera (z <= 0).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point) const;
  /// The direction through pixel position (u, v) [px] in the optical frame, with z = 1
  /// (undistorted: the inverse of project(), to 1e-9 px).
  Eigen::Vector3d ray(double u, double v) const;
  /// ray() of every pixel centre, row by row (width x height directions, z = 1).
  const std::vector<Eigen::Vector3f>& pixelRays() const { return pixel_rays_; }
  /// The widest pixel rays: the largest |x| and |y| of pixelRays() (z = 1).
  const Eigen::Vector2f& rayReach() const { return ray_reach_; }
  /// One cone per tile of kTileSide x kTileSide pixels (the last ones cut by the image's edge),
  /// row by row of tiles.
  const std::vector<TileCone>& tileCones() const { return tile_cones_; }
  /// Tiles per row of tileCones().
  int tilesAcross() const { return (width() + kTileSide - 1) / kTileSide; }
  /// pixelRays() tile by tile, row by row of tiles.
  const std::vector<TileRays>& tileRays() const { return tile_rays_; }
  /// One cone per group of kGroupSide x kGroupSide tiles, row by row of groups.
  const std::vector<TileCone>& groupCones() const { return group_cones_; }
  /// Groups per row of groupCones().
  int groupsAcross() const { return (tilesAcross() + kGroupSide - 1) / kGroupSide; }

  /// Normalised image coordinates (x/z, y/z) distorted by the Brown-Conrady model.
  Eigen::Vector2d distort(const Eigen::Vector2d& normalised) const;
  /// The inverse of distort() (Newton's method) [normalised coordinates].
  Eigen::Vector2d undistort(const Eigen::Vector2d& distorted) const;

 private:
  /// The cones of square blocks of `side` pixels, row by row.
  std::vector<TileCone> blockCones(int side) const;

  CameraIntrinsics intrinsics_;
  double f_ = 0.0, cx_ = 0.0, cy_ = 0.0;
  bool distorted_ = false;
  std::vector<Eigen::Vector3f> pixel_rays_;
  Eigen::Vector2f ray_reach_ = Eigen::Vector2f::Zero();
  std::vector<TileCone> tile_cones_, group_cones_;
  std::vector<TileRays> tile_rays_;
};

/// Where a camera's rays can go, for leaving out what they cannot meet: the planes through its
/// widest pixel rays and its far clip, at its pose.
class ViewCone {
 public:
  /// `pose`: the camera's optical frame in the env frame.
  ViewCone(const CameraModel& model, const Eigen::Isometry3d& pose);
  /// False only when no pixel ray meets the sphere of `radius` [m] about `centre` (env frame)
  /// within the far clip.
  bool mayMeet(const Eigen::Vector3d& centre, double radius) const;

 private:
  Eigen::Isometry3d to_optical_;
  std::array<Eigen::Vector3d, 4> sides_;  // outward unit normals of the four side planes
  double far_;
};

}  // namespace jetbot_rl
