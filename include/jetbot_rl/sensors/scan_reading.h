#pragma once

#include <string>
#include <vector>

namespace jetbot_rl {

/// A scan as its readings and their angles: sample k at angle_min + k x increment [rad]; REP 117
/// values (+inf no return, -inf too close, NaN unknown).
struct ScanView {
  const float* ranges = nullptr;
  int samples = 0;
  double angle_min = 0.0;  ///< [rad]
  double increment = 0.0;  ///< [rad], > 0
};

/**
 * Reads `scan` at `beam_angles` [rad, in the scan's frame] into `out` (one value per beam): beam
 * i is the smallest reading among the samples whose angle lies in its sector [angle_i,
 * angle_i + width) (-inf the smallest, NaN skipped; a scan over a full turn wraps), so that
 * nothing between two beams is lost; with `width` 0, or when no sample lies in the sector, the
 * reading of the sample nearest to the sector's middle. The simulated task and a robot's scan
 * are read by this one function. False with `error` naming the angle when a beam lies outside
 * what the scan covers (or the scan has no samples).
 */
bool readBeams(const ScanView& scan, const std::vector<double>& beam_angles, double width,
               float* out, std::string& error);

}  // namespace jetbot_rl
