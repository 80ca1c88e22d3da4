#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// How map_server turns a pixel into a cell (its `mode`).
enum class MapMode {
  kTrinary,  ///< Free 0, occupied 100, else unknown -1.
  kScale,    ///< Free 0, occupied 100, between the thresholds 1..99, transparent unknown.
  kRaw,      ///< The pixel value itself (0..255, stored as int8 as map_server does).
};

inline const EnumNameList<MapMode>& enumNames(MapMode) {
  static const EnumNameList<MapMode> names{
      {MapMode::kTrinary, "trinary"}, {MapMode::kScale, "scale"}, {MapMode::kRaw, "raw"}};
  return names;
}

/// The largest map image side accepted [px]: 67 M cells at most (under 1 GB for the world's
/// grids at about 13 bytes a cell); a larger image is refused before it is decoded.
constexpr int kMaxMapSide = 8192;

/**
 * An occupancy grid as ROS users have them: map_server's map YAML (image, resolution, origin,
 * negate, occupied_thresh, free_thresh, mode) and its PGM or PNG image, turned into cells exactly
 * as map_server turns them (the grid /map would serve). Cell (0, 0) is the image's lower-left
 * pixel; `origin` is that pixel's corner pose.
 */
struct OccupancyMap {
  std::string yaml_path;                  ///< The map YAML as given.
  std::string image_path;                 ///< The image, resolved against the YAML's folder.
  double resolution = 0.0;                ///< Cell size [m].
  double origin_x = 0.0, origin_y = 0.0;  ///< The lower-left pixel's corner [m].
  double origin_yaw = 0.0;                ///< [rad], counter-clockwise.
  bool negate = false;
  double occupied_thresh = 0.65, free_thresh = 0.196;
  MapMode mode = MapMode::kTrinary;
  int width = 0, height = 0;      ///< [cells]
  std::vector<std::int8_t> data;  ///< Row-major from the lower-left cell (OccupancyGrid order).

  /// Loads a map YAML and its image. Throws ConfigError naming the file and the missing or
  /// invalid field and its value, or the image that cannot be read or decoded or has a side
  /// above kMaxMapSide.
  static OccupancyMap fromYamlFile(const std::string& path);

  /// The cell's value (OccupancyGrid data) at column x, row y (from the bottom).
  std::int8_t at(int x, int y) const { return data[static_cast<std::size_t>(y) * width + x]; }
  /// A cell that collides and reflects beams: occupied (100) in trinary and scale mode; raw
  /// values 100 to 254.
  bool isObstacle(int x, int y) const;
  /// A cell where starts and goals may be drawn: value 0.
  bool isFree(int x, int y) const { return at(x, y) == 0; }
  /// The lower-left cell's corner pose (origin) in the map's parent frame.
  Eigen::Isometry2d pose() const {
    return Eigen::Isometry2d(Eigen::Translation2d(origin_x, origin_y) *
                             Eigen::Rotation2Dd(origin_yaw));
  }
  /// The box about the map's four corners in its parent frame [m].
  Eigen::AlignedBox2d extent() const {
    const double w = width * resolution, h = height * resolution;
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(w, 0),
                                          Eigen::Vector2d(0, h), Eigen::Vector2d(w, h)}) {
      box.extend(pose() * corner);
    }
    return box;
  }
  /// The cell (column x, row y) holding `p` (in the map's parent frame, as `origin`); false when
  /// `p` lies outside the map.
  bool cellOf(const Eigen::Vector2d& p, int& x, int& y) const {
    const Eigen::Vector2d q = pose().inverse() * p;
    x = static_cast<int>(std::floor(q.x() / resolution));
    y = static_cast<int>(std::floor(q.y() / resolution));
    return x >= 0 && y >= 0 && x < width && y < height;
  }
};

/// Writes `map` as map_saver does: `yaml_path` and its image beside it (the same name, .pgm;
/// occupied black, free 254, unknown 205; trinary thresholds). Only the cells 0, 100 and -1 are
/// kept. Throws ConfigError naming the file it cannot write.
void writeMapYaml(const OccupancyMap& map, const std::string& yaml_path);

}  // namespace jetbot_rl
