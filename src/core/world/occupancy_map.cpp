#include "jetbot_rl/world/occupancy_map.h"

#include <stb/stb_image.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

/// Field `name` of the map YAML `doc` as T; ConfigError naming the file and the field.
template <typename T>
T field(const YAML::Node& doc, const std::string& path, const char* name) {
  const YAML::Node node = doc[name];
  if (!node) throw ConfigError(path + ": missing field '" + name + "' (map_server's map YAML)");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throwInvalid(std::string(name), "'" + YAML::Dump(node) + "'",
                 "is not a valid value (in " + path + ")");
  }
}

}  // namespace

bool OccupancyMap::isObstacle(int x, int y) const {
  const std::int8_t v = at(x, y);
  if (mode == MapMode::kRaw) {
    const auto raw = static_cast<std::uint8_t>(v);
    return raw >= 100 && raw <= 254;
  }
  return v == 100;
}

OccupancyMap OccupancyMap::fromYamlFile(const std::string& path) {
  namespace fs = std::filesystem;
  OccupancyMap map;
  map.yaml_path = path;
  YAML::Node doc;
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ConfigError("map YAML '" + path + "' cannot be read: it " + problem);
  }
  try {
    doc = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ConfigError("map YAML '" + path + "' cannot be read");
  } catch (const YAML::Exception& e) {
    throw ConfigError("map YAML '" + path + "' is not YAML: " + e.what());
  }
  if (!doc.IsMap()) throw ConfigError("map YAML '" + path + "' is not a map of fields");
  const std::string image = field<std::string>(doc, path, "image");
  map.resolution = field<double>(doc, path, "resolution");
  const std::vector<double> origin = field<std::vector<double>>(doc, path, "origin");
  map.negate = field<int>(doc, path, "negate") != 0;
  map.occupied_thresh = field<double>(doc, path, "occupied_thresh");
  map.free_thresh = field<double>(doc, path, "free_thresh");
  if (doc["mode"]) map.mode = parseEnum<MapMode>("mode", field<std::string>(doc, path, "mode"));
  const std::string in = " (in " + path + ")";
  if (!std::isfinite(map.resolution) || map.resolution <= 0.0) {
    throwInvalid("resolution", map.resolution, "must be > 0 m" + in);
  }
  if (origin.size() != 3 || !std::isfinite(origin[0]) || !std::isfinite(origin[1]) ||
      !std::isfinite(origin[2])) {
    throwInvalid("origin", listText(origin), "must be [x, y, yaw], finite" + in);
  }
  map.origin_x = origin[0];
  map.origin_y = origin[1];
  map.origin_yaw = origin[2];
  if (!(map.free_thresh >= 0.0 && map.free_thresh < map.occupied_thresh &&
        map.occupied_thresh <= 1.0)) {
    throwInvalid("free_thresh", map.free_thresh,
                 "must be in [0, occupied_thresh = " + std::to_string(map.occupied_thresh) +
                     ") with occupied_thresh <= 1" + in);
  }
  const fs::path image_path =
      fs::path(image).is_absolute() ? fs::path(image) : fs::path(path).parent_path() / image;
  map.image_path = image_path.string();

  if (const std::string problem = fileProblem(map.image_path); !problem.empty()) {
    throwInvalid("image", "'" + map.image_path + "'", problem + in);
  }
  int w = 0, h = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
      stbi_load(map.image_path.c_str(), &w, &h, &channels, 0), stbi_image_free);
  if (!pixels) {
    throwInvalid("image", "'" + map.image_path + "'",
                 std::string("cannot be read as an image: ") + stbi_failure_reason() + in);
  }
  map.width = w;
  map.height = h;
  map.data.assign(static_cast<std::size_t>(w) * h, -1);
  // map_server's image_loader: the mean of the colour channels (the alpha channel too in trinary
  // mode), the last channel standing for alpha (even without one), rows flipped so that cell
  // (0, 0) is the lower-left pixel.
  const bool has_alpha = channels == 2 || channels == 4;
  const int averaged = (map.mode == MapMode::kTrinary || !has_alpha) ? channels : channels - 1;
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const unsigned char* p = pixels.get() + (static_cast<std::size_t>(j) * w + i) * channels;
      int sum = 0;
      for (int k = 0; k < averaged; ++k) sum += p[k];
      double color = static_cast<double>(sum) / averaged;
      const int alpha = channels == 1 ? 1 : p[channels - 1];
      if (map.negate) color = 255.0 - color;
      std::int8_t value;
      if (map.mode == MapMode::kRaw) {
        value = static_cast<std::int8_t>(static_cast<int>(color));
      } else {
        const double occ = (255.0 - color) / 255.0;
        if (occ > map.occupied_thresh) {
          value = 100;
        } else if (occ < map.free_thresh) {
          value = 0;
        } else if (map.mode == MapMode::kTrinary || alpha < 1) {
          value = -1;
        } else {
          const double ratio = (occ - map.free_thresh) / (map.occupied_thresh - map.free_thresh);
          value = static_cast<std::int8_t>(1 + 98 * ratio);
        }
      }
      map.data[static_cast<std::size_t>(h - j - 1) * w + i] = value;
    }
  }
  return map;
}

void writeMapYaml(const OccupancyMap& map, const std::string& yaml_path) {
  namespace fs = std::filesystem;
  const fs::path yaml(yaml_path);
  const fs::path image = fs::path(yaml).replace_extension(".pgm");
  std::ofstream pgm(image, std::ios::binary);
  // map_saver's image: rows from the top, occupied 0 (black), free 254, unknown 205.
  pgm << "P5\n# written by jetbot_rl\n" << map.width << " " << map.height << "\n255\n";
  for (int y = map.height - 1; y >= 0; --y) {
    for (int x = 0; x < map.width; ++x) {
      const std::int8_t v = map.at(x, y);
      pgm.put(static_cast<char>(v == 0 ? 254 : v == -1 ? 205 : 0));
    }
  }
  std::ofstream out(yaml);
  out.precision(15);  // as short as the value allows, within a double's last bit
  out << "image: " << image.filename().string() << "\nresolution: " << map.resolution
      << "\norigin: [" << map.origin_x << ", " << map.origin_y << ", " << map.origin_yaw
      << "]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  if (!pgm || !out) throw ConfigError("cannot write the map " + yaml_path + " and its image");
}

}  // namespace jetbot_rl
