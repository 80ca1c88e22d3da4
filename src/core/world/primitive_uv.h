#pragma once
// Texture coordinates on a box, cylinder or sphere, for a texture its material names.
#include <Eigen/Core>
#include <vector>

namespace jetbot_rl {

/// The shapes primitiveUv() spreads a texture over.
enum class UvShape { kBox, kCylinder, kSphere };

/// Texture coordinates of the corners `local` of a `shape` of `size` (a box's x, y, z; a
/// cylinder's radius and length; a sphere's radius [m]) in its own frame (its surface's
/// triangles), as Gazebo's and RViz's meshes of them spread a texture: across each face of a box
/// (from left to right as seen from outside, and up; the top and bottom along x and y), around and
/// along a cylinder's side and across its caps, around a sphere and from pole to pole.
std::vector<Eigen::Vector2f> primitiveUv(UvShape shape, const Eigen::Vector3d& size,
                                         const std::vector<Eigen::Vector3d>& local);

}  // namespace jetbot_rl
