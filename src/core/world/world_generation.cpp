#include "jetbot_rl/world/world_generation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "world/barn_field.h"

namespace jetbot_rl {
namespace {

Obstacle box(const Eigen::Vector2d& center, double half_x, double half_y, double yaw,
             double height) {
  Obstacle o;
  o.shape = Obstacle::Shape::kBox;
  o.center = center;
  o.half_extents = Eigen::Vector2d(half_x, half_y);
  o.yaw = yaw;
  o.height = height;
  return o;
}

/// A post (cylinder) or a crate (box) of bounding radius at most `max_radius`, at `center`.
Obstacle thing(Rng& rng, const Eigen::Vector2d& center, double max_radius, double height) {
  if (rng.uniform() < 0.5) {
    Obstacle o;
    o.shape = Obstacle::Shape::kCylinder;
    o.center = center;
    o.radius = uniform(rng, 0.2 * max_radius, max_radius);
    o.height = height;
    return o;
  }
  const double side = max_radius * std::sqrt(2.0);  // its diagonal within 2 x max_radius
  return box(center, 0.5 * uniform(rng, 0.3 * side, side), 0.5 * uniform(rng, 0.3 * side, side),
             uniform(rng, -kPi, kPi), height);
}

/// Clutter: a grid of cells each a passage plus an obstacle wide, inset by half a passage from
/// the walls; each cell holds an obstacle with a probability growing with difficulty, anywhere
/// that keeps half a passage from the cell's edges: obstacles stay a passage apart.
void clutter(double d, const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
             int& left_out) {
  const double passage = narrowestPassage(a, d), thing_radius = 0.15;
  const Eigen::Vector2d lo = a.area.min().array() + 0.5 * passage;
  const Eigen::Vector2d size = (a.area.sizes().array() - passage).max(0.0);
  const double cell = passage + 2.0 * thing_radius;
  const int nx = std::max(1, static_cast<int>(size.x() / cell));
  const int ny = std::max(1, static_cast<int>(size.y() / cell));
  const Eigen::Vector2d step(size.x() / nx, size.y() / ny);
  const double fill = lerp(0.4, 0.9, d);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      if (rng.uniform() >= fill) continue;
      const double r = uniform(rng, 0.04, thing_radius);
      const Eigen::Vector2d corner = lo + Eigen::Vector2d(i * step.x(), j * step.y());
      const double slack_x = std::max(0.0, step.x() - passage - 2.0 * r);
      const double slack_y = std::max(0.0, step.y() - passage - 2.0 * r);
      const Eigen::Vector2d center =
          corner + Eigen::Vector2d(0.5 * passage + r + slack_x * rng.uniform(),
                                   0.5 * passage + r + slack_y * rng.uniform());
      addObstacle(thing(rng, center, r, a.height), max, out, left_out);
    }
  }
}

/// A wall from `from` to `to` (axis-aligned) with a door of `door` at a random place along it.
void wallWithDoor(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double door,
                  const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
                  int& left_out) {
  const Eigen::Vector2d along = to - from;
  const double length = along.norm();
  const Eigen::Vector2d unit = along / length;
  const double margin = 0.5 * a.wall_thickness;
  const double opening = std::min(door, length - 2.0 * margin);
  const double at = uniform(rng, margin, length - margin - opening);  // the door's start
  const double yaw = std::atan2(unit.y(), unit.x());
  for (const auto& [s0, s1] :
       {std::array<double, 2>{0.0, at}, std::array<double, 2>{at + opening, length}}) {
    if (s1 - s0 <= 1e-6) continue;
    addObstacle(box(from + unit * (0.5 * (s0 + s1)), 0.5 * (s1 - s0), 0.5 * a.wall_thickness, yaw,
                    a.height),
                max, out, left_out);
  }
}

/// Rooms: a grid of 2 x 2 to 4 x 4 rooms, a door in every wall between two of them, furniture
/// growing with difficulty, kept a passage away from the walls.
void rooms(double d, const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
           int& left_out) {
  const double passage = narrowestPassage(a, d);
  const int n = 2 + static_cast<int>(std::lround(2.0 * d));
  const Eigen::Vector2d lo = a.area.min(), size = a.area.sizes();
  const Eigen::Vector2d room(size.x() / n, size.y() / n);
  const double door = std::max(passage, lerp(1.2, 0.0, d));
  for (int k = 1; k < n; ++k) {  // the walls between rows and between columns, room by room
    for (int m = 0; m < n; ++m) {
      const double x = lo.x() + k * room.x(), y = lo.y() + k * room.y();
      wallWithDoor({x, lo.y() + m * room.y()}, {x, lo.y() + (m + 1) * room.y()}, door, a, rng, max,
                   out, left_out);
      wallWithDoor({lo.x() + m * room.x(), y}, {lo.x() + (m + 1) * room.x(), y}, door, a, rng, max,
                   out, left_out);
    }
  }
  const int furniture = static_cast<int>(std::lround(lerp(0.0, 3.0, d)));
  const double keep = passage + 0.5 * a.wall_thickness;  // from the walls, doors included
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d corner = lo + Eigen::Vector2d(i * room.x(), j * room.y());
      for (int f = 0; f < furniture; ++f) {
        const double r = uniform(rng, 0.05, 0.25);
        const double free_x = room.x() - 2.0 * (keep + r), free_y = room.y() - 2.0 * (keep + r);
        if (free_x <= 0.0 || free_y <= 0.0) continue;
        const Eigen::Vector2d c = corner + Eigen::Vector2d(keep + r + free_x * rng.uniform(),
                                                           keep + r + free_y * rng.uniform());
        addObstacle(thing(rng, c, r, a.height), max, out, left_out);
      }
    }
  }
}

/// A perfect maze by a depth-first walk (the recursive backtracker) over cells of 1.6 m down to
/// the narrowest passage and a wall, from a random cell; a wall between every two cells the walk
/// did not join.
void maze(double d, const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
          int& left_out) {
  const double target = std::max(narrowestPassage(a, d) + a.wall_thickness, lerp(1.6, 0.6, d));
  const Eigen::Vector2d lo = a.area.min(), size = a.area.sizes();
  const int nx = std::max(1, static_cast<int>(size.x() / target));
  const int ny = std::max(1, static_cast<int>(size.y() / target));
  const Eigen::Vector2d cell(size.x() / nx, size.y() / ny);
  // open[c][0]: the passage east of cell c is open; open[c][1]: north.
  std::vector<std::array<bool, 2>> open(static_cast<std::size_t>(nx) * ny, {false, false});
  std::vector<std::uint8_t> seen(open.size(), 0);
  std::vector<int> stack{static_cast<int>(rng.uniform() * nx * ny) % (nx * ny)};
  seen[stack.back()] = 1;
  while (!stack.empty()) {
    const int c = stack.back(), x = c % nx, y = c / nx;
    std::array<int, 4> next{};
    int count = 0;
    for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int nx2 = x + dx, ny2 = y + dy;
      if (nx2 >= 0 && nx2 < nx && ny2 >= 0 && ny2 < ny && !seen[ny2 * nx + nx2]) {
        next[count++] = ny2 * nx + nx2;
      }
    }
    if (count == 0) {
      stack.pop_back();
      continue;
    }
    const int to = next[static_cast<int>(rng.uniform() * count) % count];
    const bool across = to / nx == c / nx;         // east or west, else north or south
    open[std::min(c, to)][across ? 0 : 1] = true;  // east of the left one, north of the lower
    seen[to] = 1;
    stack.push_back(to);
  }
  const double t = a.wall_thickness;
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      const Eigen::Vector2d c0 = lo + Eigen::Vector2d(x * cell.x(), y * cell.y());
      if (x + 1 < nx && !open[y * nx + x][0]) {
        addObstacle(box(c0 + Eigen::Vector2d(cell.x(), 0.5 * cell.y()), 0.5 * t,
                        0.5 * (cell.y() + t), 0.0, a.height),
                    max, out, left_out);
      }
      if (y + 1 < ny && !open[y * nx + x][1]) {
        addObstacle(box(c0 + Eigen::Vector2d(0.5 * cell.x(), cell.y()), 0.5 * (cell.x() + t),
                        0.5 * t, 0.0, a.height),
                    max, out, left_out);
      }
    }
  }
}

/// A family index by world/family_weights (all alike when empty), from one draw.
int pickFamily(const WorldConfig& c, Rng& rng) {
  const int n = static_cast<int>(c.families.size());
  const auto weight = [&](int i) { return c.family_weights.empty() ? 1.0 : c.family_weights[i]; };
  double total = 0.0;
  for (int i = 0; i < n; ++i) total += weight(i);
  double u = rng.uniform() * total;
  int last = 0;
  for (int i = 0; i < n; ++i) {
    if (weight(i) <= 0.0) continue;
    if (u < weight(i)) return i;
    u -= weight(i);
    last = i;
  }
  return last;  // rounding at the top end
}

GenerationArea areaOf(const WorldModel& world) {
  GenerationArea a;
  a.area = world.region();
  a.robot_radius = world.robotRadius();
  a.height = world.config().obstacle_height;
  a.wall_thickness = world.config().wall_thickness;
  a.passage_widths_hard = world.config().passage_widths[0];
  a.passage_widths_easy = world.config().passage_widths[1];
  return a;
}

/// The obstacles of family `family` at `difficulty`; with a fixed start, none within the start
/// clearance of it (dropping obstacles only opens a layout up).
void generateFor(const WorldModel& world, int family, double difficulty, Rng& rng,
                 EnvLayout& layout) {
  const WorldConfig& c = world.config();
  layout.obstacles.clear();
  layout.family = family;
  layout.difficulty = difficulty;
  layout.given_up =
      generateObstacles(parseEnum<WorldFamily>("world/families", c.families[family]), difficulty,
                        areaOf(world), rng, c.max_generated_obstacles, layout.obstacles);
  if (!c.random_start) {
    const double keep = world.startClearance();
    layout.obstacles.erase(std::remove_if(layout.obstacles.begin(), layout.obstacles.end(),
                                          [&](const Obstacle& o) {
                                            return o.distance(Eigen::Vector2d::Zero()) < keep;
                                          }),
                           layout.obstacles.end());
  }
}

/// A start the robot can stand on in `grid` with the start clearance: drawn (random_start) or
/// the origin; false when none is found.
bool drawGeneratedStart(const WorldModel& world, const FootprintGrid& grid, Rng& rng,
                        EnvLayout& layout) {
  const auto fits = [&](const Eigen::Vector2d& p) {
    return fitsGeneratedStart(world, grid, layout.obstacles, p);
  };
  if (!world.config().random_start) {
    layout.start = Eigen::Vector2d::Zero();
    return fits(layout.start);
  }
  const Eigen::AlignedBox2d& r = world.region();
  for (int k = 0; k < world.config().placement_tries; ++k) {
    const Eigen::Vector2d p(uniform(rng, r.min().x(), r.max().x()),
                            uniform(rng, r.min().y(), r.max().y()));
    if (fits(p)) {
      layout.start = p;
      return true;
    }
  }
  return false;
}

}  // namespace

void drawGeneratedLayout(const WorldModel& world, Rng& rng, int env, double difficulty,
                         WorldDrawing* task, EnvLayout& layout) {
  for (int attempt = 0; attempt < kLayoutAttempts; ++attempt) {
    generateFor(world, pickFamily(world.config(), rng), difficulty, rng, layout);
    FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles);
    if (!drawGeneratedStart(world, grid, rng, layout)) continue;
    grid.reachFrom(layout.start);
    WorldDraft draft;
    draft.start = layout.start;
    draft.obstacles = &layout.obstacles;
    draft.reach = &grid;
    std::vector<Eigen::Vector2d> keep_free{layout.start};
    if (task && !task->drawInWorld(env, rng, world, draft, keep_free)) continue;
    layout.unmade = false;
    return;
  }
  // Counted and flagged, so a trainer sees it; the episode still has a start and a goal.
  layout.obstacles.clear();
  layout.given_up = 0;
  layout.unmade = true;
  world.drawStart(rng, layout);
  WorldDraft draft;
  draft.start = layout.start;
  std::vector<Eigen::Vector2d> keep_free{layout.start};
  if (task) task->drawInWorld(env, rng, world, draft, keep_free);
}

bool fitsGeneratedStart(const WorldModel& world, const FootprintGrid& grid,
                        const std::vector<Obstacle>& obstacles, const Eigen::Vector2d& p) {
  return grid.isFree(p) && world.isClear(p, world.startClearance(), obstacles);
}

FootprintGrid drawSharedGeneratedLayout(const WorldModel& world, Rng& rng, double difficulty,
                                        EnvLayout& layout) {
  for (int attempt = 0; attempt < kLayoutAttempts; ++attempt) {
    generateFor(world, pickFamily(world.config(), rng), difficulty, rng, layout);
    FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles);
    EnvLayout trial = layout;  // the robots draw their own starts: this one only shows there is one
    if (!drawGeneratedStart(world, grid, rng, trial)) continue;
    layout.unmade = false;
    return grid;
  }
  layout.obstacles.clear();
  layout.given_up = 0;
  layout.unmade = true;
  return FootprintGrid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles);
}

void checkGeneratedLayouts(const WorldModel& world) {
  const WorldConfig& c = world.config();
  constexpr int kTrials = 8;
  for (double d : {c.difficulty, c.curriculum ? 1.0 : c.difficulty}) {
    for (int f = 0; f < static_cast<int>(c.families.size()); ++f) {
      bool any = false;
      for (int k = 0; k < kTrials && !any; ++k) {
        Rng rng(0, static_cast<std::uint64_t>(k));
        EnvLayout layout;
        generateFor(world, f, d, rng, layout);
        const FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(),
                                 layout.obstacles);
        any = drawGeneratedStart(world, grid, rng, layout);
      }
      if (!any) {
        throwInvalid("world/difficulty", d,
                     "family " + c.families[f] + " leaves no start with " +
                         std::to_string(world.startClearance()) + " m of clearance in the " +
                         std::to_string(c.arena_size[0]) + " x " + std::to_string(c.arena_size[1]) +
                         " m arena (world/arena_size, world/start_clearance)");
      }
    }
  }
}

double narrowestPassage(const GenerationArea& a, double difficulty) {
  const double width = 2.0 * a.robot_radius;
  return lerp(a.passage_widths_easy * width, a.passage_widths_hard * width,
              std::clamp(difficulty, 0.0, 1.0));
}

int generateObstacles(WorldFamily family, double difficulty, const GenerationArea& area, Rng& rng,
                      int max_obstacles, std::vector<Obstacle>& out) {
  const double d = std::clamp(difficulty, 0.0, 1.0);
  int left_out = 0;
  switch (family) {
    case WorldFamily::kClutter:
      clutter(d, area, rng, max_obstacles, out, left_out);
      break;
    case WorldFamily::kRooms:
      rooms(d, area, rng, max_obstacles, out, left_out);
      break;
    case WorldFamily::kMaze:
      maze(d, area, rng, max_obstacles, out, left_out);
      break;
    case WorldFamily::kBarn:
      barnField(d, area, rng, max_obstacles, out, left_out);
      break;
  }
  return left_out;
}

}  // namespace jetbot_rl
