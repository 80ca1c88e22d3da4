#pragma once
// An image on a surface (a mesh material's diffuse texture), as the camera samples it.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace jetbot_rl {

/// The largest side of a texture read [px]: 8192 x 8192 RGB is 192 MiB.
constexpr int kMaxTextureSide = 8192;
/// The decoded bytes of all the textures of one world, or of one robot's visuals: 1 GiB (AWS's
/// small house takes 287 MiB).
constexpr std::size_t kMaxTextureBytes = std::size_t{1} << 30;

/// A decoded texture, RGB row by row from the top left.
struct TextureImage {
  std::string path;  ///< The file it was read from.
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width x height x 3

  /// The colour in [0, 1] at texture coordinates (u, v) (v up: v = 0 is the bottom row, as in
  /// OpenGL and assimp; repeated outside [0, 1]): the nearest texel. Non-finite: the first texel.
  Eigen::Vector3f at(float u, float v) const;
};

/// Reads the image file at `path` (PNG, JPEG, TGA, BMP, ...: stb_image) as RGB, its alpha left
/// out, and adds its bytes to `*bytes` (with `bytes`). ModelError naming the path and why: not a
/// regular file, not an image, a side over kMaxTextureSide, or (with `bytes`) more than
/// kMaxTextureBytes with those counted before (refused from its header, before it is decoded).
std::shared_ptr<const TextureImage> loadTextureImage(const std::string& path,
                                                     std::size_t* bytes = nullptr);

}  // namespace jetbot_rl
