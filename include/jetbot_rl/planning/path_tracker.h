#pragma once

#include <Eigen/Core>
#include <vector>

namespace jetbot_rl {

/**
 * Where a robot is along a path (a polyline of waypoints), as a local planner follows a global
 * plan: the nearest point of the path near where the robot was last (within a window of arc
 * length, so that a path folding back behind a wall is not jumped to), what is left of the path
 * from there, and a look-ahead point further along.
 */
class PathTracker {
 public:
  /// Arc length searched behind and ahead of the last position [m].
  static constexpr double kBehind = 0.5, kAhead = 1.5;

  /// Follows `points` (at least one) from its start.
  void reset(std::vector<Eigen::Vector2d> points);
  /// Moves to the point of the path nearest `p` within the window.
  void track(const Eigen::Vector2d& p);
  /// The path left from the tracked point, plus `p`'s distance from it [m].
  double remaining(const Eigen::Vector2d& p) const;
  /// `p`'s distance from the tracked point [m]: how far the robot strayed from the path.
  double offset(const Eigen::Vector2d& p) const { return (p - pointAt(at_)).norm(); }
  /// The point `distance` [m] along the path past the tracked point (the goal at the end).
  Eigen::Vector2d lookahead(double distance) const;
  const std::vector<Eigen::Vector2d>& points() const { return points_; }
  /// The path's length [m].
  double length() const { return along_.empty() ? 0.0 : along_.back(); }

 private:
  Eigen::Vector2d pointAt(double s) const;

  std::vector<Eigen::Vector2d> points_{Eigen::Vector2d::Zero()};
  std::vector<double> along_{0.0};  // arc length to each point [m]
  double at_ = 0.0;                 // the tracked point's arc length [m]
};

}  // namespace jetbot_rl
