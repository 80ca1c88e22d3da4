#pragma once

#include <sensor_msgs/LaserScan.h>

#include <string>
#include <vector>

#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {

/// The scan beams a navigation policy observes.
struct ScanBeams {
  std::vector<double> angles;  ///< In the scanner's frame, in observation order [rad].
  double range_min = 0.0;      ///< The trained scanner's range: readings are clamped into it...
  double range_max = 0.0;      ///< ... and divided by range_max [m] (the observer does).
  double width = 0.0;          ///< Each beam's sector [rad] (readBeams()); 0: the nearest sample.
};

/// The beams of a policy's observation contract (its checkpoint's spec.observer); none when it
/// observes no scan.
ScanBeams scanBeamsOf(const ObserverSpec& trained);

/// The readings of `scan` at the policy's `beams` into `ranges`, as the simulated task reads its
/// own scan (readBeams(), scan_reading.h: each beam the smallest reading of its sector, REP 117
/// values as the scan holds them; a scan with a negative increment read in its angles' order).
/// False with `error` naming the angles when a beam lies outside what the scan covers.
bool resampleScan(const sensor_msgs::LaserScan& scan, const ScanBeams& beams,
                  std::vector<float>& ranges, std::string& error);

}  // namespace jetbot_rl
