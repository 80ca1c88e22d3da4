#include "jetbot_rl/world/occupancy_map.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"
#include "world/map_yaml.h"

namespace jetbot_rl {

bool OccupancyMap::isObstacle(int x, int y) const {
  const std::int8_t v = at(x, y);
  if (mode == MapMode::kRaw) {
    const auto raw = static_cast<std::uint8_t>(v);
    return raw >= 100 && raw <= 254;
  }
  return v == 100;
}

OccupancyMap OccupancyMap::fromYamlFile(const std::string& path) {
  OccupancyMap map;
  map.yaml_path = path;
  const MapYaml yaml = readMapYaml(path, "map YAML");
  const YAML::Node& doc = yaml.doc;
  map.resolution = yaml.resolution;
  map.origin_x = yaml.origin_x;
  map.origin_y = yaml.origin_y;
  map.origin_yaw = yaml.origin_yaw;
  map.image_path = yaml.image_path;
  map.negate = mapYamlField<int>(doc, path, "negate") != 0;
  map.occupied_thresh = mapYamlField<double>(doc, path, "occupied_thresh");
  map.free_thresh = mapYamlField<double>(doc, path, "free_thresh");
  if (doc["mode"]) {
    map.mode = parseEnum<MapMode>("mode", mapYamlField<std::string>(doc, path, "mode"));
  }
  const std::string in = " (in " + path + ")";
  if (!(map.free_thresh >= 0.0 && map.free_thresh < map.occupied_thresh &&
        map.occupied_thresh <= 1.0)) {
    throwInvalid("free_thresh", map.free_thresh,
                 "must be in [0, occupied_thresh = " + std::to_string(map.occupied_thresh) +
                     ") with occupied_thresh <= 1" + in);
  }
  const MapImage image = decodeMapImage(yaml, path, 0, kMaxMapSide);
  const int w = image.width, h = image.height, channels = image.channels;
  const unsigned char* const pixels = image.pixels.get();
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
      const unsigned char* p = pixels + (static_cast<std::size_t>(j) * w + i) * channels;
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
