#include "jetbot_rl/tasks/observer_spec.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace jetbot_rl {

namespace {

/// speed_limit_path and speed_limit_distances are both empty or [front, left > right] and
/// [0 <= stop < slow], finite.
void checkSpeedLimit(const ObserverSpec& s) {
  const auto finite = [](const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
  };
  const std::vector<double>& path = s.speed_limit_path;
  const std::vector<double>& d = s.speed_limit_distances;
  if (path.empty() != d.empty()) {
    throwInvalid(path.empty() ? "speed_limit_distances" : "speed_limit_path",
                 listText(path.empty() ? d : path),
                 "speed_limit_path and speed_limit_distances are given together or not at all");
  }
  if (path.empty()) return;
  if (path.size() != 3 || !finite(path) || !(path[1] > path[2])) {
    throwInvalid("speed_limit_path", listText(path),
                 "must be [front x, left y, right y] [m] with left > right");
  }
  if (d.size() != 2 || !finite(d) || !(d[0] >= 0.0 && d[0] < d[1])) {
    throwInvalid("speed_limit_distances", listText(d),
                 "must be [stop_distance, slow_distance] [m] with 0 <= stop < slow");
  }
}

}  // namespace

void checkFieldRules(const ObserverSpec& s) {
  if (!s.camera_image.empty() && s.camera_image != "rgb") {
    throwInvalid("camera_image", s.camera_image, "must be rgb or empty");
  }
  const bool image = !s.camera_image.empty();
  for (const auto& [name, side] :
       {std::pair{"camera_width", s.camera_width}, std::pair{"camera_height", s.camera_height}}) {
    if (image ? side < 1 || side > 4096 : side != 0) {
      throwInvalid(
          name, side,
          image ? "must be in [1, 4096] with a camera_image" : "must be 0 without a camera_image");
    }
  }
  if (!s.scan_source.empty() && s.scan_source != "camera_depth") {
    throwInvalid("scan_source", s.scan_source, "must be camera_depth or empty (a laser)");
  }
  if (s.scan_source.empty()
          ? !s.scan_heights.empty()
          : s.scan_heights.size() != 2 || !(s.scan_heights[0] < s.scan_heights[1])) {
    throwInvalid("scan_heights", listText(s.scan_heights),
                 s.scan_source.empty() ? "must be empty with a laser's scan"
                                       : "must be [min, max] with min < max with camera_depth");
  }
  checkSpeedLimit(s);
  if (s.scan_beam_angles.empty()) {
    if (!s.scan_range.empty()) {
      throwInvalid("scan_range", listText(s.scan_range), "must be empty without scan beams");
    }
    return;
  }
  if (s.scan_range.size() != 2 || !(s.scan_range[0] >= 0.0 && s.scan_range[0] < s.scan_range[1])) {
    throwInvalid(
        "scan_range", listText(s.scan_range),
        "must be [range_min, range_max] with 0 <= range_min < range_max with scan beams (" +
            std::to_string(s.scan_beam_angles.size()) + " given)");
  }
}

}  // namespace jetbot_rl
