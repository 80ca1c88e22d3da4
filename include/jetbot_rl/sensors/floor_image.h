#pragma once

// A picture laid on the ground for the camera (world/floor): a user's photographed track, tape
// lines, a carpet. Read from a YAML beside the image as map_server reads a map's (image,
// resolution, origin); placed in every env's frame as a map is.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jetbot_rl {

/// The largest floor image side accepted [px].
constexpr int kMaxFloorSide = 8192;

/// A floor image in the env frame: pixel (0, 0) of `rgb` is the image's lower-left pixel, whose
/// corner is at `origin`.
struct FloorImage {
  std::string yaml_path;                  ///< The YAML as given.
  std::string image_path;                 ///< The image, resolved against the YAML's folder.
  double resolution = 0.0;                ///< [m per pixel]
  double origin_x = 0.0, origin_y = 0.0;  ///< The lower-left pixel's corner [m].
  double origin_yaw = 0.0;                ///< [rad], counter-clockwise.
  int width = 0, height = 0;              ///< [px]
  std::vector<std::uint8_t> rgb;  ///< width x height x 3, row-major from the lower-left pixel.
  float cos_yaw = 1.0f, sin_yaw = 0.0f;  ///< Of origin_yaw, for colourAt().
  /// The colour of the ground beyond the image (a painted track's floor), or none: the ground's.
  std::optional<Eigen::Vector3f> outside;

  /// Loads the YAML (image, resolution, origin; map_server's other fields are not needed) and its
  /// image (PNG, PGM, JPEG, ...: grey, grey + alpha, RGB or RGBA, the alpha ignored). Throws
  /// ConfigError naming `world/floor`, the file and the field, or an image that cannot be read or
  /// has a side above kMaxFloorSide px.
  static FloorImage fromYamlFile(const std::string& path);

  /// The colour at (x, y) of the env frame [m] (each channel in [0, 1], the nearest pixel's);
  /// false outside the image (unless `outside` is set, which it gives there).
  bool colourAt(float x, float y, Eigen::Vector3f& colour) const;
};

}  // namespace jetbot_rl
