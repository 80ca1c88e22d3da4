#include "jetbot_rl/sensors/scan_reading.h"

#include <cmath>
#include <limits>

namespace jetbot_rl {
namespace {

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

bool readBeams(const ScanView& scan, const std::vector<double>& beam_angles, double width,
               float* out, std::string& error) {
  const int n = scan.samples;
  const double inc = scan.increment;
  if (n < 1 || !scan.ranges || !std::isfinite(inc) || inc <= 0.0 ||
      !std::isfinite(scan.angle_min)) {
    error = "the scan has no samples or no angle increment";
    return false;
  }
  // A scan over a full turn wraps: a sector or a nearest sample past its end continues at its
  // start.
  const bool full_turn = inc * n >= kTwoPi - inc * 1.5;
  const auto sample = [&](long k) -> long {
    if (!full_turn) return k >= 0 && k < n ? k : -1;
    return ((k % n) + n) % n;
  };
  for (std::size_t i = 0; i < beam_angles.size(); ++i) {
    const double from = (beam_angles[i] - scan.angle_min) / inc;  // [samples]
    float best = std::numeric_limits<float>::quiet_NaN();
    if (width > 0.0) {
      // Samples k with from <= k < from + width / inc, give or take a thousandth of a sample: a
      // LaserScan's float angles are that far off after hundreds of samples.
      const long first = static_cast<long>(std::ceil(from - 1e-3));
      const long end = static_cast<long>(std::ceil(from + width / inc - 1e-3));
      for (long k = first; k < end; ++k) {
        const long s = sample(k);
        if (s < 0) continue;
        const float r = scan.ranges[s];
        if (!std::isnan(r) && (std::isnan(best) || r < best)) best = r;
      }
    }
    if (std::isnan(best)) {
      const long s = sample(std::lround(from + 0.5 * width / inc));
      if (s < 0) {
        error = "the scan covers [" + std::to_string(scan.angle_min) + ", " +
                std::to_string(scan.angle_min + inc * (n - 1)) +
                "] rad; the policy needs a beam at " + std::to_string(beam_angles[i]) + " rad";
        return false;
      }
      best = scan.ranges[s];
    }
    out[i] = best;
  }
  return true;
}

}  // namespace jetbot_rl
