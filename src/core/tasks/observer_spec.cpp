#include "jetbot_rl/tasks/observer_spec.h"

#include <string>

namespace jetbot_rl {

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
