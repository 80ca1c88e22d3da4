#include "jetbot_rl/ros/deploy/scan_beams.h"

#include <cmath>

#include "jetbot_rl/sensors/scan_reading.h"

namespace jetbot_rl {

bool resampleScan(const sensor_msgs::LaserScan& scan, const ObserverSpec& trained,
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
  ranges.resize(trained.scan_beam_angles.size());
  return readBeams(view, trained.scan_beam_angles, trained.scan_beam_width, ranges.data(), error);
}

}  // namespace jetbot_rl
