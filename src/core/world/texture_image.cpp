#include "jetbot_rl/world/texture_image.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {

namespace {

/// Coordinate `c` repeated into [0, 1), as the texel index of `size` texels.
int texel(float c, int size) {
  const float wrapped = c - std::floor(c);
  return std::min(static_cast<int>(wrapped * static_cast<float>(size)), size - 1);
}

}  // namespace

Eigen::Vector3f TextureImage::at(float u, float v) const {
  std::size_t i = 0;
  if (std::isfinite(u) && std::isfinite(v)) {
    const int x = texel(u, width), y = height - 1 - texel(v, height);
    i = 3 * (static_cast<std::size_t>(y) * width + x);
  }
  constexpr float kByte = 1.0f / 255.0f;
  return Eigen::Vector3f(rgb[i], rgb[i + 1], rgb[i + 2]) * kByte;
}

std::shared_ptr<const TextureImage> loadTextureImage(const std::string& path, std::size_t* bytes) {
  const auto refuse = [&](const std::string& why) {
    throw ModelError("texture '" + path + "' " + why);
  };
  if (const std::string problem = fileProblem(path); !problem.empty()) refuse(problem);
  int width = 0, height = 0, channels = 0;
  if (!stbi_info(path.c_str(), &width, &height, &channels)) {
    refuse(std::string("cannot be read as an image: ") + stbi_failure_reason());
  }
  if (width > kMaxTextureSide || height > kMaxTextureSide) {
    refuse("is " + std::to_string(width) + " x " + std::to_string(height) + " px: at most " +
           std::to_string(kMaxTextureSide) + " px a side");
  }
  const std::size_t size = 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (bytes && *bytes + size > kMaxTextureBytes) {
    constexpr std::size_t kMiB = std::size_t{1} << 20;
    refuse("would make " + std::to_string((*bytes + size + kMiB - 1) / kMiB) +
           " MiB of textures, more than the " + std::to_string(kMaxTextureBytes / kMiB) +
           " MiB allowed");
  }
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{
      stbi_load(path.c_str(), &width, &height, &channels, 3), stbi_image_free};
  if (!pixels || width <= 0 || height <= 0) {
    refuse(std::string("cannot be read as an image: ") + stbi_failure_reason());
  }
  auto image = std::make_shared<TextureImage>();
  image->path = path;
  image->width = width;
  image->height = height;
  image->rgb.assign(pixels.get(), pixels.get() + 3 * static_cast<std::size_t>(width) * height);
  if (bytes) *bytes += image->rgb.size();
  return image;
}

}  // namespace jetbot_rl
