// The `barn` family (src/core/world/barn_field.cpp): BARN's cellular-automaton fields of posts,
// scaled to the robot; its starts and goals are checked with the other families'
// (test_world_generation.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "jetbot_rl/world/world_generation.h"

namespace jetbot_rl {
namespace {

TEST(BarnField, PostsOnCellsWhoseThreeCellGapsNarrowWithDifficulty) {
  GenerationArea area;
  area.area = Eigen::AlignedBox2d(Eigen::Vector2d(-3, -3), Eigen::Vector2d(3, 3));
  area.robot_radius = 0.1;
  const double width = 0.2;
  std::map<double, double> mean_count;
  for (double d : {0.0, 0.5, 1.0}) {
    const double lo_gap = (1.5 - 0.45 * d) * width, hi_gap = (1.8 - 0.5 * d) * width;
    int total = 0;
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      Rng rng(11, seed);
      std::vector<Obstacle> out;
      ASSERT_EQ(generateObstacles(WorldFamily::kBarn, d, area, rng, 100000, out), 0);
      ASSERT_FALSE(out.empty());
      total += static_cast<int>(out.size());
      // Posts of one radius, half a cell, on one lattice of cells: three cells a gap in range.
      const double cell = 2.0 * out[0].radius;
      EXPECT_GE(3.0 * cell, lo_gap - 1e-9) << "difficulty " << d << " seed " << seed;
      EXPECT_LE(3.0 * cell, hi_gap + 1e-9) << "difficulty " << d << " seed " << seed;
      for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_EQ(out[i].shape, Obstacle::Shape::kCylinder);
        ASSERT_EQ(out[i].radius, out[0].radius);
        const Eigen::Vector2d reach = Eigen::Vector2d::Constant(out[i].radius);
        EXPECT_TRUE(area.area.contains(Eigen::Vector2d(out[i].center + reach)));
        EXPECT_TRUE(area.area.contains(Eigen::Vector2d(out[i].center - reach)));
        const Eigen::Vector2d steps = (out[i].center - out[0].center) / cell;
        EXPECT_NEAR(steps.x(), std::round(steps.x()), 1e-6);
        EXPECT_NEAR(steps.y(), std::round(steps.y()), 1e-6);
      }
    }
    mean_count[d] = total / 10.0;
  }
  EXPECT_GT(mean_count[0.5], mean_count[0.0]);
  EXPECT_GT(mean_count[1.0], mean_count[0.5]);
  // No post inside a ring of eight (out of every reach), and hardly a lone post in a field grown
  // from lone cells (unsmoothed, 0.7^8: 6 % of them would be): the smoothing ran.
  Rng rng(11, 99);
  std::vector<Obstacle> out;
  generateObstacles(WorldFamily::kBarn, 1.0, area, rng, 100000, out);
  const double cell = 2.0 * out[0].radius;
  std::set<std::pair<long, long>> at;
  for (const Obstacle& o : out) {
    at.insert({std::lround((o.center - out[0].center).x() / cell),
               std::lround((o.center - out[0].center).y() / cell)});
  }
  int lone = 0;
  for (const auto& [x, y] : at) {
    int ring = 0;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) ring += (dx || dy) && at.count({x + dx, y + dy});
    }
    EXPECT_LT(ring, 8) << "post at cell " << x << ", " << y;
    lone += ring == 0;
  }
  EXPECT_LT(lone, 0.01 * at.size());
}

}  // namespace
}  // namespace jetbot_rl
