#include "jetbot_rl/sensors/floor_image.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/errors.h"
#include "world/map_yaml.h"

namespace jetbot_rl {

FloorImage FloorImage::fromYamlFile(const std::string& path) {
  FloorImage floor;
  floor.yaml_path = path;
  try {
    const MapYaml yaml = readMapYaml(path, "floor YAML");
    floor.image_path = yaml.image_path;
    floor.resolution = yaml.resolution;
    floor.origin_x = yaml.origin_x;
    floor.origin_y = yaml.origin_y;
    floor.origin_yaw = yaml.origin_yaw;
    floor.cos_yaw = static_cast<float>(std::cos(yaml.origin_yaw));
    floor.sin_yaw = static_cast<float>(std::sin(yaml.origin_yaw));
    const MapImage image = decodeMapImage(yaml, path, 3, kMaxFloorSide);
    const int w = image.width, h = image.height;
    const unsigned char* pixels = image.pixels.get();
    floor.width = w;
    floor.height = h;
    floor.rgb.resize(static_cast<std::size_t>(w) * h * 3);
    // Rows flipped: the image's top row is the floor's far (+y) edge, as a map's.
    for (int j = 0; j < h; ++j) {
      const unsigned char* row = pixels + static_cast<std::size_t>(j) * w * 3;
      std::copy(row, row + static_cast<std::size_t>(w) * 3,
                floor.rgb.begin() + static_cast<std::ptrdiff_t>(h - 1 - j) * w * 3);
    }
  } catch (const ConfigError& e) {
    throw ConfigError(std::string("world/floor: ") + e.what());
  }
  return floor;
}

bool FloorImage::colourAt(float x, float y, Eigen::Vector3f& colour) const {
  const float dx = x - static_cast<float>(origin_x), dy = y - static_cast<float>(origin_y);
  const float u = (cos_yaw * dx + sin_yaw * dy) / static_cast<float>(resolution);
  const float v = (-sin_yaw * dx + cos_yaw * dy) / static_cast<float>(resolution);
  if (!(u >= 0.0f && v >= 0.0f && u < width && v < height)) {
    if (!outside) return false;
    colour = *outside;
    return true;
  }
  const std::size_t i = (static_cast<std::size_t>(v) * width + static_cast<std::size_t>(u)) * 3;
  colour = Eigen::Vector3f(rgb[i], rgb[i + 1], rgb[i + 2]) / 255.0f;
  return true;
}

}  // namespace jetbot_rl
