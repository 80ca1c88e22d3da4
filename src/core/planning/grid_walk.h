#pragma once

// The cells a ray crosses on a grid of unit cells, in order (Amanatides and Woo): the scanner's
// beams through a map (scan_cast.cpp) and a Gazebo world's outlines traced into its grid
// (world_cut.cpp).

#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace jetbot_rl {

/// A walk along p + t v [cells] from cell (x, y), the one holding the point it starts at.
class GridWalk {
 public:
  GridWalk(const Eigen::Vector2d& p, const Eigen::Vector2d& v, long x0, long y0)
      : x(x0), y(y0), step_x_(v.x() > 0 ? 1 : -1), step_y_(v.y() > 0 ? 1 : -1) {
    const double inf = std::numeric_limits<double>::infinity();
    delta_x_ = v.x() != 0.0 ? std::abs(1.0 / v.x()) : inf;
    delta_y_ = v.y() != 0.0 ? std::abs(1.0 / v.y()) : inf;
    next_x_ = v.x() != 0.0 ? ((x + (step_x_ > 0 ? 1 : 0)) - p.x()) / v.x() : inf;
    next_y_ = v.y() != 0.0 ? ((y + (step_y_ > 0 ? 1 : 0)) - p.y()) / v.y() : inf;
  }
  /// Into the next cell; the t at which the ray enters it.
  double advance() {
    if (next_x_ < next_y_) {
      const double t = next_x_;
      next_x_ += delta_x_;
      x += step_x_;
      return t;
    }
    const double t = next_y_;
    next_y_ += delta_y_;
    y += step_y_;
    return t;
  }

  long x, y;  ///< The cell the walk is in.

 private:
  long step_x_, step_y_;
  double delta_x_ = 0.0, delta_y_ = 0.0, next_x_ = 0.0, next_y_ = 0.0;
};

}  // namespace jetbot_rl
