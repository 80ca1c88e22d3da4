#include "jetbot_rl/planning/grid_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace jetbot_rl {
namespace {

/// The octile distance between two cells [cells]: the length of the shortest 8-neighbour path.
double octile(long dx, long dy) {
  const double a = static_cast<double>(std::abs(dx)), b = static_cast<double>(std::abs(dy));
  return std::max(a, b) + (std::sqrt(2.0) - 1.0) * std::min(a, b);
}

/// True when every cell along a to b (sampled at a quarter cell) is free with `clearance` or more.
bool inSight(const FootprintGrid& grid, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
             double clearance) {
  const double length = (b - a).norm();
  const int samples = static_cast<int>(std::ceil(length / (0.25 * grid.resolution()))) + 1;
  for (int k = 0; k <= samples; ++k) {
    const long c = grid.cellOf(a + (b - a) * (static_cast<double>(k) / samples));
    if (!grid.isFreeCell(c) || grid.clearance(c) < clearance) return false;
  }
  return true;
}

}  // namespace

bool planPath(const FootprintGrid& grid, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
              double clearance_cost, std::vector<Eigen::Vector2d>& path) {
  path.clear();
  const long s = grid.cellOf(start), g = grid.cellOf(goal);
  if (!grid.isFreeCell(s) || !grid.isFreeCell(g)) return false;
  const long w = grid.width(), n = w * grid.height();
  const double radius = grid.robotRadius(), margin = grid.clearanceCap() - radius;
  const auto cellCost = [&](long c) {
    const double beyond = std::clamp((grid.clearance(c) - radius) / margin, 0.0, 1.0);
    return 1.0 + clearance_cost * (1.0 - beyond);
  };
  std::vector<double> cost(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<long> parent(static_cast<std::size_t>(n), -1);
  using Entry = std::pair<double, long>;  // (cost so far + estimate, cell): the smallest first
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  const auto estimate = [&](long c) { return octile(c % w - g % w, c / w - g / w); };
  cost[s] = 0.0;
  open.push({estimate(s), s});
  while (!open.empty()) {
    const auto [f, c] = open.top();
    open.pop();
    if (c == g) break;
    if (f > cost[c] + estimate(c) + 1e-9) continue;  // a stale entry
    const long x = c % w, y = c / w;
    for (long dy = -1; dy <= 1; ++dy) {
      for (long dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const long nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= grid.height()) continue;
        const long m = ny * w + nx;
        if (!grid.isFreeCell(m)) continue;
        // A diagonal step needs both cells beside it free: no corner is cut.
        if (dx != 0 && dy != 0 && (!grid.isFreeCell(y * w + nx) || !grid.isFreeCell(ny * w + x))) {
          continue;
        }
        const double step = (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0) * cellCost(m);
        if (cost[c] + step < cost[m]) {
          cost[m] = cost[c] + step;
          parent[m] = c;
          open.push({cost[m] + estimate(m), m});
        }
      }
    }
  }
  if (!std::isfinite(cost[g])) return false;
  std::vector<long> cells;
  for (long c = g; c != -1; c = parent[c]) cells.push_back(c);
  std::reverse(cells.begin(), cells.end());
  // Straightened (string pulling): from each kept cell, on to the farthest cell in sight, over
  // cells no nearer the walls than the stretch it replaces; the start and the goal themselves.
  cells.front() = -1;  // stands for the start
  cells.back() = -2;   // and the goal
  const auto point = [&](long c) { return c == -1 ? start : c == -2 ? goal : grid.centre(c); };
  path.push_back(start);
  std::size_t i = 0;
  while (i + 1 < cells.size()) {
    std::size_t j = i + 1;
    double least = std::min(grid.clearance(grid.cellOf(point(cells[i]))),
                            grid.clearance(grid.cellOf(point(cells[j]))));
    while (j + 1 < cells.size()) {
      const double next = std::min(least, grid.clearance(grid.cellOf(point(cells[j + 1]))));
      if (!inSight(grid, point(cells[i]), point(cells[j + 1]), next)) break;
      least = next;
      ++j;
    }
    if (j + 1 < cells.size()) path.push_back(point(cells[j]));
    i = j;
  }
  path.push_back(goal);
  return true;
}

}  // namespace jetbot_rl
