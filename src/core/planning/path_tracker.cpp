#include "jetbot_rl/planning/path_tracker.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace jetbot_rl {

void PathTracker::reset(std::vector<Eigen::Vector2d> points) {
  if (points.empty()) points.push_back(Eigen::Vector2d::Zero());
  points_ = std::move(points);
  along_.assign(points_.size(), 0.0);
  for (std::size_t i = 1; i < points_.size(); ++i) {
    along_[i] = along_[i - 1] + (points_[i] - points_[i - 1]).norm();
  }
  at_ = 0.0;
}

void PathTracker::track(const Eigen::Vector2d& p) {
  if (points_.size() < 2) return;
  double best = std::numeric_limits<double>::infinity(), best_at = at_;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    if (along_[i + 1] < at_ - kBehind) continue;
    if (along_[i] > at_ + kAhead) break;
    const Eigen::Vector2d a = points_[i], ab = points_[i + 1] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double d = (a + t * ab - p).squaredNorm();
    if (d < best) {
      best = d;
      best_at = along_[i] + t * (along_[i + 1] - along_[i]);
    }
  }
  at_ = best_at;
}

double PathTracker::remaining(const Eigen::Vector2d& p) const {
  return (length() - at_) + offset(p);
}

Eigen::Vector2d PathTracker::lookahead(double distance) const { return pointAt(at_ + distance); }

Eigen::Vector2d PathTracker::pointAt(double s) const {
  if (s <= 0.0 || points_.size() < 2) return points_.front();
  if (s >= along_.back()) return points_.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(along_.begin(), along_.end(), s) -
                                                 along_.begin() - 1);
  const double span = along_[i + 1] - along_[i];
  const double t = span > 0.0 ? (s - along_[i]) / span : 0.0;
  return points_[i] + t * (points_[i + 1] - points_[i]);
}

}  // namespace jetbot_rl
