#pragma once

// The part of a map_server map YAML that places an image on the ground (image, resolution,
// origin), shared by the occupancy map (world/map) and the camera's floor image (world/floor).

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

/// A map YAML's document and its image's placement: cell (0, 0) is the image's lower-left pixel,
/// `origin` that pixel's corner pose.
struct MapYaml {
  YAML::Node doc;
  std::string image_path;   ///< `image`, resolved against the YAML's folder.
  double resolution = 0.0;  ///< [m per pixel]
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;  ///< [m], [rad]
};

/// Field `name` of the YAML `doc` read from `path`, as T; ConfigError naming the file and field.
template <typename T>
T mapYamlField(const YAML::Node& doc, const std::string& path, const char* name) {
  const YAML::Node node = doc[name];
  if (!node) throw ConfigError(path + ": missing field '" + name + "' (map_server's map YAML)");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throwInvalid(std::string(name), "'" + YAML::Dump(node) + "'",
                 "is not a valid value (in " + path + ")");
  }
}

/// Reads the YAML at `path` (a `kind`, e.g. "map YAML", in messages) and its image, resolution
/// and origin; ConfigError naming the file and the missing or invalid field, or an image file
/// that cannot be read.
MapYaml readMapYaml(const std::string& path, const std::string& kind);

/// A decoded image (stb_image), row-major from its top-left pixel.
struct MapImage {
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, nullptr};
  int width = 0, height = 0;
  int channels =
      0;  ///< As stored in the file (the pixels have `channels` of decodeMapImage's, if given).
};

/// Decodes `yaml`'s image (read from `path`) with `channels` per pixel (0: as stored); with
/// `max_side` > 0 an image with a larger side is refused from its header, before it is decoded.
/// ConfigError naming `image`, the file and `path`.
MapImage decodeMapImage(const MapYaml& yaml, const std::string& path, int channels = 0,
                        int max_side = 0);

}  // namespace jetbot_rl
