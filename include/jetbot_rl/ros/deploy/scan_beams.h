#pragma once

#include <sensor_msgs/LaserScan.h>

#include <string>
#include <vector>

#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {

/// The readings of `scan` at the beams of the policy's observation contract `trained` (its
/// scan_beam_angles and scan_beam_width) into `ranges`, as the simulated task reads its
/// own scan (readBeams(), scan_reading.h: each beam the smallest reading of its sector, REP 117
/// values as the scan holds them; a scan with a negative increment read in its angles' order).
/// False with `error` naming the angles when a beam lies outside what the scan covers.
bool resampleScan(const sensor_msgs::LaserScan& scan, const ObserverSpec& trained,
                  std::vector<float>& ranges, std::string& error);

}  // namespace jetbot_rl
