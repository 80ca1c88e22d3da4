#include "jetbot_rl/tasks/observer_spec.h"

#include <string>

namespace jetbot_rl {

void checkFieldRules(const ObserverSpec& s) {
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
