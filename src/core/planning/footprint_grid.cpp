#include "jetbot_rl/planning/footprint_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace jetbot_rl {

FootprintGrid::FootprintGrid(const WorldModel& world, double resolution, double robot_radius,
                             const std::vector<Obstacle>& obstacles, double margin)
    : area_(world.region()),
      resolution_(resolution),
      robot_radius_(robot_radius),
      cap_(robot_radius + std::max(margin, resolution)) {
  width_ = std::max(1, static_cast<int>(std::ceil(area_.sizes().x() / resolution)));
  height_ = std::max(1, static_cast<int>(std::ceil(area_.sizes().y() / resolution)));
  clearance_.resize(static_cast<std::size_t>(width_) * height_);
  for (long c = 0; c < static_cast<long>(clearance_.size()); ++c) {
    clearance_[c] = static_cast<float>(std::min(cap_, world.staticClearance(centre(c))));
  }
  // Each obstacle lowers the cells within its reach only.
  for (const Obstacle& o : obstacles) {
    if (!o.placed) continue;
    const double reach = o.boundingRadius() + cap_;
    const auto index = [&](double v, double lo, int n) {
      return std::clamp(static_cast<int>(std::floor((v - lo) / resolution)), 0, n - 1);
    };
    const int x0 = index(o.center.x() - reach, area_.min().x(), width_);
    const int x1 = index(o.center.x() + reach, area_.min().x(), width_);
    const int y0 = index(o.center.y() - reach, area_.min().y(), height_);
    const int y1 = index(o.center.y() + reach, area_.min().y(), height_);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const long c = static_cast<long>(y) * width_ + x;
        const double d = std::max(0.0, o.distance(centre(c)));
        if (d < clearance_[c]) clearance_[c] = static_cast<float>(d);
      }
    }
  }
  reached_.assign(clearance_.size(), 0);
}

long FootprintGrid::cellOf(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d q = (p - area_.min()) / resolution_;
  if (!(q.x() >= 0.0 && q.y() >= 0.0)) return -1;  // NaN too
  const long x = static_cast<long>(q.x()), y = static_cast<long>(q.y());
  if (x >= width_ || y >= height_) return -1;
  return y * width_ + x;
}

Eigen::Vector2d FootprintGrid::centre(long cell) const {
  return area_.min() + resolution_ * Eigen::Vector2d(static_cast<double>(cell % width_) + 0.5,
                                                     static_cast<double>(cell / width_) + 0.5);
}

bool FootprintGrid::reachFrom(const Eigen::Vector2d& start) {
  std::fill(reached_.begin(), reached_.end(), 0);
  const long s = cellOf(start);
  if (!isFreeCell(s)) return false;
  std::deque<long> queue{s};
  reached_[s] = 1;
  while (!queue.empty()) {
    const long c = queue.front();
    queue.pop_front();
    const long x = c % width_, y = c / width_;
    for (const auto& [dx, dy] : {std::array<long, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const long nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
      const long n = ny * width_ + nx;
      if (isFreeCell(n) && !reached_[n]) {
        reached_[n] = 1;
        queue.push_back(n);
      }
    }
  }
  return true;
}

bool FootprintGrid::reachable(const Eigen::Vector2d& p) const {
  const long c = cellOf(p);
  return c >= 0 && reached_[c];
}

}  // namespace jetbot_rl
