#pragma once

#include <cmath>

namespace jetbot_rl {

/// pi, for angles [rad]
inline constexpr double kPi = 3.14159265358979323846;

/// True for a finite value above 0 (sizes, masses, radii).
inline bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

/// a at t = 0, b at t = 1, linear between (C++20's std::lerp).
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace jetbot_rl
