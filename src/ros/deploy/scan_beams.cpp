#include "jetbot_rl/ros/deploy/scan_beams.h"

#include <cmath>

#include "jetbot_rl/sensors/scan_reading.h"

namespace jetbot_rl {

ScanBeams scanBeamsOf(const BatchSpec& trained, const DriverParams& p,
                      const std::string& checkpoint) {
  ScanBeams beams;
  if (trained.scan_beam_angles.empty() || trained.scan_range.size() != 2) {
    if (p.scan_beams == 0 || p.scan_angles.empty() || p.scan_range.empty()) {
      const char* missing = p.scan_beams == 0       ? "scan_beams"
                            : p.scan_angles.empty() ? "scan_angles"
                                                    : "scan_range";
      throwInvalid(missing, p.scan_beams == 0 ? "0" : "[]",
                   "checkpoint " + checkpoint +
                       " does not hold the scan beams it was trained on (written before "
                       "checkpoints held them): give the trained scanner's scan_beams (nav/beams "
                       "of its training), scan_angles [first, last] and scan_range [min, max]");
    }
    const int k = p.scan_beams;
    for (int i = 0; i < k; ++i) {
      beams.angles.push_back(k == 1 ? p.scan_angles[0]
                                    : p.scan_angles[0] +
                                          i * (p.scan_angles[1] - p.scan_angles[0]) / (k - 1));
    }
    beams.range_min = p.scan_range[0];
    beams.range_max = p.scan_range[1];
    return beams;
  }
  beams.angles = trained.scan_beam_angles;
  beams.range_min = trained.scan_range[0];
  beams.range_max = trained.scan_range[1];
  beams.width = trained.scan_beam_width;
  // Given as well: they must say what the checkpoint says (anything else would misread the scan).
  const std::string leave = " (leave it unset: the checkpoint gives it)";
  if (p.scan_beams != 0 && p.scan_beams != static_cast<int>(beams.angles.size())) {
    throwInvalid("scan_beams", p.scan_beams,
                 "the policy of " + checkpoint + " was trained with " +
                     std::to_string(beams.angles.size()) + " beams" + leave);
  }
  const auto agree = [&](const char* name, const std::vector<double>& given, double first,
                         double last, const char* unit) {
    if (given.empty()) return;
    if (std::abs(given[0] - first) > 1e-6 || std::abs(given[1] - last) > 1e-6) {
      throwInvalid(name, listText(given),
                   std::string("the policy of ") + checkpoint + " was trained with " +
                       listText(std::vector<double>{first, last}) + " " + unit + leave);
    }
  };
  agree("scan_angles", p.scan_angles, beams.angles.front(), beams.angles.back(), "rad");
  agree("scan_range", p.scan_range, beams.range_min, beams.range_max, "m");
  return beams;
}

bool resampleScan(const sensor_msgs::LaserScan& scan, const ScanBeams& beams,
                  std::vector<float>& ranges, std::string& error) {
  ScanView view{scan.ranges.data(), static_cast<int>(scan.ranges.size()), scan.angle_min,
                scan.angle_increment};
  thread_local std::vector<float> reversed;
  if (scan.angle_increment < 0.0f) {  // clockwise: the same samples in ascending angles
    reversed.assign(scan.ranges.rbegin(), scan.ranges.rend());
    view.ranges = reversed.data();
    view.angle_min = scan.angle_min + static_cast<double>(scan.angle_increment) *
                                          static_cast<double>(scan.ranges.size() - 1);
    view.increment = -static_cast<double>(scan.angle_increment);
  }
  ranges.resize(beams.angles.size());
  return readBeams(view, beams.angles, beams.width, ranges.data(), error);
}

}  // namespace jetbot_rl
