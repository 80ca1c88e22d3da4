#include "world/map_yaml.h"

#include <stb/stb_image.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/config/file_checks.h"

namespace jetbot_rl {

MapYaml readMapYaml(const std::string& path, const std::string& kind) {
  namespace fs = std::filesystem;
  MapYaml out;
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ConfigError(kind + " '" + path + "' cannot be read: it " + problem);
  }
  try {
    out.doc = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ConfigError(kind + " '" + path + "' cannot be read");
  } catch (const YAML::Exception& e) {
    throw ConfigError(kind + " '" + path + "' is not YAML: " + e.what());
  }
  if (!out.doc.IsMap()) throw ConfigError(kind + " '" + path + "' is not a map of fields");
  const std::string image = mapYamlField<std::string>(out.doc, path, "image");
  out.resolution = mapYamlField<double>(out.doc, path, "resolution");
  const std::vector<double> origin = mapYamlField<std::vector<double>>(out.doc, path, "origin");
  const std::string in = " (in " + path + ")";
  if (!std::isfinite(out.resolution) || out.resolution <= 0.0) {
    throwInvalid("resolution", out.resolution, "must be > 0 m" + in);
  }
  if (origin.size() != 3 || !std::isfinite(origin[0]) || !std::isfinite(origin[1]) ||
      !std::isfinite(origin[2])) {
    throwInvalid("origin", listText(origin), "must be [x, y, yaw], finite" + in);
  }
  out.origin_x = origin[0];
  out.origin_y = origin[1];
  out.origin_yaw = origin[2];
  const fs::path image_path =
      fs::path(image).is_absolute() ? fs::path(image) : fs::path(path).parent_path() / image;
  out.image_path = image_path.string();
  if (const std::string problem = fileProblem(out.image_path); !problem.empty()) {
    throwInvalid("image", "'" + out.image_path + "'", problem + in);
  }
  return out;
}

MapImage decodeMapImage(const MapYaml& yaml, const std::string& path, int channels, int max_side) {
  const std::string in = " (in " + path + ")";
  const std::string file = "'" + yaml.image_path + "'";
  MapImage image;
  if (max_side > 0) {
    if (!stbi_info(yaml.image_path.c_str(), &image.width, &image.height, &image.channels)) {
      throwInvalid("image", file,
                   std::string("cannot be read as an image: ") + stbi_failure_reason() + in);
    }
    if (image.width > max_side || image.height > max_side) {
      throwInvalid("image", file,
                   "is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                       " px: at most " + std::to_string(max_side) + " px a side" + in);
    }
  }
  image.pixels = {
      stbi_load(yaml.image_path.c_str(), &image.width, &image.height, &image.channels, channels),
      stbi_image_free};
  if (!image.pixels) {
    throwInvalid("image", file,
                 std::string("cannot be read as an image: ") + stbi_failure_reason() + in);
  }
  return image;
}

}  // namespace jetbot_rl
