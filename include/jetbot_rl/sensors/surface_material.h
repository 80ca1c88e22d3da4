#pragma once
// What a drawn surface shows: a colour, or a texture at its triangles' corners' coordinates.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "jetbot_rl/world/texture_image.h"

namespace jetbot_rl {

/// The material of one Embree triangle geometry.
struct SurfaceMaterial {
  Eigen::Vector3f colour{0.7f, 0.7f, 0.7f};     ///< Diffuse RGB in [0, 1], without a texture.
  std::shared_ptr<const TextureImage> texture;  ///< Drawn instead of `colour`, or nullptr.
  std::vector<Eigen::Vector2f> uv;              ///< With `texture`: coordinates per corner.

  /// The colour at triangle `triangle` where Embree's barycentric coordinates are `u`, `v`.
  Eigen::Vector3f at(unsigned triangle, float u, float v) const {
    if (!texture) return colour;
    // Embree's hit is (1 - u - v) a + u b + v c.
    const Eigen::Vector2f* corner = &uv[3 * static_cast<std::size_t>(triangle)];
    const Eigen::Vector2f p = (1.0f - u - v) * corner[0] + u * corner[1] + v * corner[2];
    return texture->at(p.x(), p.y());
  }
};

}  // namespace jetbot_rl
