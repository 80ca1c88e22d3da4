#pragma once
// Texture coordinates on a box, cylinder or sphere, for a material script's texture.
#include <Eigen/Core>
#include <sdf/sdf.hh>
#include <vector>

namespace jetbot_rl {

/// Texture coordinates of the corners `local` of primitive `g`'s surface in its own frame
/// (sdfSurface()'s triangles), as Gazebo's meshes of them spread a texture: across each face of
/// a box (horizontal along a side face, up its height), around and along a cylinder's side and
/// across its caps, around a sphere and from pole to pole. Empty for any other geometry.
std::vector<Eigen::Vector2f> primitiveUv(const sdf::Geometry& g,
                                         const std::vector<Eigen::Vector3d>& local);

}  // namespace jetbot_rl
