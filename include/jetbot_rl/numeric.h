#pragma once

#include <cmath>

namespace jetbot_rl {

/// pi, for angles [rad]
inline constexpr double kPi = 3.14159265358979323846;

/// True for a finite value above 0 (sizes, masses, radii).
inline bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace jetbot_rl
