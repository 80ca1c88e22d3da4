#include "world/barn_field.h"

#include <algorithm>
#include <cstdint>

#include "jetbot_rl/numeric.h"

namespace jetbot_rl {
namespace {

/// Filled cells among the 8 around (x, y); cells outside the grid count as empty.
int filledAround(const std::vector<std::uint8_t>& cells, int nx, int ny, int x, int y) {
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int cx = x + dx, cy = y + dy;
      if ((dx != 0 || dy != 0) && cx >= 0 && cx < nx && cy >= 0 && cy < ny) {
        n += cells[static_cast<std::size_t>(cy) * nx + cx];
      }
    }
  }
  return n;
}

}  // namespace

void barnField(double d, const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
               int& left_out) {
  // BARN's cells are 0.15 m for a 0.43 m wide Jackal: three empty cells between two posts are the
  // narrowest gap it drives through (1.05 widths). Here three cells are a gap drawn in
  // [1.5, 1.8] robot widths at difficulty 0 down to [1.05, 1.3] at 1, and the field grows denser
  // (a cell starts filled with probability 0.15 to 0.3; denser fields leave no start with its
  // clearance and no goal a path reaches).
  const double width = 2.0 * a.robot_radius;
  const double gap = width * lerp(lerp(1.5, 1.05, d), lerp(1.8, 1.3, d), rng.uniform());
  const double cell = gap / 3.0;
  const int nx = std::max(1, static_cast<int>(a.area.sizes().x() / cell));
  const int ny = std::max(1, static_cast<int>(a.area.sizes().y() / cell));
  const Eigen::Vector2d lo =
      a.area.center() - 0.5 * cell * Eigen::Vector2d(static_cast<double>(nx), ny);
  const double fill = lerp(0.15, 0.3, d);
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(nx) * ny), next(cells.size());
  for (auto& c : cells) c = rng.uniform() < fill ? 1 : 0;
  // BARN's smoothing: a cell with 5 or more filled neighbours fills, one with 1 or none empties,
  // so lone posts go and clumps grow into walls with gaps between them.
  constexpr int kSmoothing = 4;
  for (int it = 0; it < kSmoothing; ++it) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        const int n = filledAround(cells, nx, ny, x, y);
        const std::size_t i = static_cast<std::size_t>(y) * nx + x;
        next[i] = n >= 5 ? 1 : n <= 1 ? 0 : cells[i];
      }
    }
    cells.swap(next);
  }
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      // A post ringed by eight touching posts is out of the robot's and the beams' reach.
      if (!cells[static_cast<std::size_t>(y) * nx + x] || filledAround(cells, nx, ny, x, y) == 8) {
        continue;
      }
      Obstacle post;
      post.shape = Obstacle::Shape::kCylinder;
      post.center = lo + cell * Eigen::Vector2d(x + 0.5, y + 0.5);
      post.radius = 0.5 * cell;
      post.height = a.height;
      addObstacle(post, max, out, left_out);
    }
  }
}

}  // namespace jetbot_rl
