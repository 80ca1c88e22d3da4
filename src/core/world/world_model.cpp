#include "jetbot_rl/world/world_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/world_generation.h"

namespace jetbot_rl {
namespace {

/// Felzenszwalb and Huttenlocher's 1-D squared distance transform of `f` (n values, stride
/// `stride`; far cells hold kFar) in place.
constexpr double kFar = 1e20;
void distanceTransform1d(double* f, int n, int stride, std::vector<double>& d, std::vector<int>& v,
                         std::vector<double>& z) {
  const double inf = std::numeric_limits<double>::infinity();
  d.resize(n);
  v.assign(n, 0);
  z.assign(n + 1, 0.0);
  const auto at = [&](int q) { return f[static_cast<std::size_t>(q) * stride]; };
  const auto meet = [&](int q, int p) {  // where the parabolas of q and p intersect
    return ((at(q) + double(q) * q) - (at(p) + double(p) * p)) / (2.0 * (q - p));
  };
  int k = 0;
  z[0] = -inf;
  z[1] = inf;
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (s <= z[k]) s = meet(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = inf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = double(q - v[k]) * (q - v[k]) + at(v[k]);
  }
  for (int q = 0; q < n; ++q) f[static_cast<std::size_t>(q) * stride] = d[q];
}

Obstacle wall(double cx, double cy, double hx, double hy, double height) {
  Obstacle w;
  w.shape = Obstacle::Shape::kBox;
  w.center = {cx, cy};
  w.half_extents = {hx, hy};
  w.height = height;
  return w;
}

}  // namespace

double Obstacle::distance(const Eigen::Vector2d& p) const {
  if (shape == Shape::kCylinder) return (p - center).norm() - radius;
  const Eigen::Vector2d q = Eigen::Rotation2Dd(-yaw) * (p - center);
  const Eigen::Vector2d d = q.cwiseAbs() - half_extents;
  return d.cwiseMax(0.0).norm() + std::min(std::max(d.x(), d.y()), 0.0);
}

void checkFieldRules(const WorldConfig& c) {
  if (!c.gazebo_world.empty() && !c.map.empty()) {
    throwInvalid("world/gazebo_world", c.gazebo_world,
                 "must be empty with world/map (" + c.map +
                     "): one static world per env; the Gazebo world makes its own grid");
  }
  if (c.spawn.size() != 2) throwInvalid("world/spawn", listText(c.spawn), "must be [x, y]");
  if (!c.arena_size.empty() && c.arena_size.size() != 2) {
    throwInvalid("world/arena_size", listText(c.arena_size), "must be [x, y] or []");
  }
  if (!c.region.empty() &&
      (c.region.size() != 4 || c.region[0] >= c.region[2] || c.region[1] >= c.region[3])) {
    throwInvalid("world/region", listText(c.region),
                 "must be [x_min, y_min, x_max, y_max] with min < max, or []");
  }
  if (c.families.empty()) {
    if (c.curriculum) {
      throwInvalid("world/curriculum", "true", "needs world/families (it raises their difficulty)");
    }
    return;
  }
  for (const std::string& f : c.families) parseEnum<WorldFamily>("world/families", f);
  if (c.arena_size.size() != 2 || !c.map.empty()) {
    throwInvalid("world/families", listText(c.families),
                 "generated layouts fill an arena: give world/arena_size and no world/map");
  }
  if (!c.region.empty()) {
    throwInvalid("world/region", listText(c.region),
                 "must be [] with world/families (generated layouts fill the arena)");
  }
  if (c.num_boxes > 0 || c.num_cylinders > 0) {
    throwInvalid(c.num_boxes > 0 ? "world/num_boxes" : "world/num_cylinders",
                 c.num_boxes > 0 ? c.num_boxes : c.num_cylinders,
                 "must be 0 with world/families (a generated layout has its own obstacles)");
  }
  if (!c.family_weights.empty()) {
    if (c.family_weights.size() != c.families.size()) {
      throwInvalid(
          "world/family_weights", listText(c.family_weights),
          "must have one weight per family (" + std::to_string(c.families.size()) + ") or be []");
    }
    double total = 0.0;
    for (double w : c.family_weights) total += w;
    if (!(total > 0.0)) {
      throwInvalid("world/family_weights", listText(c.family_weights), "must not be all 0");
    }
  }
}

WorldModel::WorldModel(const WorldConfig& config, double robot_radius)
    : WorldModel(config, robot_radius, nullptr) {}

WorldModel::WorldModel(const WorldConfig& config, double robot_radius, const OccupancyMap& map)
    : WorldModel(config, robot_radius, &map) {}

WorldModel::WorldModel(const WorldConfig& config, double robot_radius, const OccupancyMap* loaded)
    : config_(config), robot_radius_(robot_radius) {
  if (loaded) {
    map_ = *loaded;
  } else if (!config_.map.empty()) {
    try {
      map_ = OccupancyMap::fromYamlFile(config_.map);
    } catch (const ConfigError& e) {
      throw ConfigError(std::string("world/map: ") + e.what());
    }
  }
  if (!loaded && !config_.gazebo_world.empty()) readGazeboWorld();
  if (map_) {
    map_pose_ = map_->pose();
    if (obstacle_cells_.empty()) {  // a Gazebo world has set them: its cells that are geometry
      obstacle_cells_.resize(map_->data.size());
      for (int y = 0; y < map_->height; ++y) {
        for (int x = 0; x < map_->width; ++x) {
          obstacle_cells_[static_cast<std::size_t>(y) * map_->width + x] = map_->isObstacle(x, y);
        }
      }
    }
    mergeObstacleCells();
    computeDistanceField();
  }
  const double h = config_.obstacle_height, t = config_.wall_thickness;
  if (config_.arena_size.size() == 2) {
    const double x = 0.5 * config_.arena_size[0], y = 0.5 * config_.arena_size[1];
    walls_.push_back(wall(x + 0.5 * t, 0.0, 0.5 * t, y + t, h));
    walls_.push_back(wall(-x - 0.5 * t, 0.0, 0.5 * t, y + t, h));
    walls_.push_back(wall(0.0, y + 0.5 * t, x, 0.5 * t, h));
    walls_.push_back(wall(0.0, -y - 0.5 * t, x, 0.5 * t, h));
  }
  if (config_.region.size() == 4) {
    region_ = Eigen::AlignedBox2d(Eigen::Vector2d(config_.region[0], config_.region[1]),
                                  Eigen::Vector2d(config_.region[2], config_.region[3]));
  } else if (config_.arena_size.size() == 2) {
    const Eigen::Vector2d half(0.5 * config_.arena_size[0], 0.5 * config_.arena_size[1]);
    region_ = Eigen::AlignedBox2d(-half, half);
  } else if (map_) {
    region_ = map_->extent();
  }
  const bool draws = config_.random_start || config_.num_boxes > 0 || config_.num_cylinders > 0 ||
                     !config_.families.empty();
  if (draws && region_.isEmpty()) {
    throwInvalid("world/region", "[]",
                 "random starts and obstacles need somewhere to go: give world/region, "
                 "world/arena_size or world/map");
  }
  // A start must fit: the origin, or somewhere in the region.
  start_clearance_ = std::max(config_.start_clearance, robot_radius);
  if (!config_.draws) return;
  const double clearance = start_clearance_;
  if (!config_.families.empty()) checkGeneratedLayouts(*this);
  if (!config_.random_start) {
    const Eigen::Vector2d spawn(config_.spawn[0], config_.spawn[1]);
    if (gazebo_ && staticClearance(spawn) < clearance) {
      throwInvalid("world/spawn", listText(config_.spawn),
                   "the fixed start is not free with " + std::to_string(clearance) +
                       " m of clearance (world/start_clearance or the robot's footprint): " +
                       gazeboSolidNear(spawn, clearance));
    }
    if (staticClearance(spawn) < clearance) {
      throwInvalid(spawn.isZero() ? "world/random_start" : "world/spawn",
                   spawn.isZero() ? "false" : listText(config_.spawn),
                   "the fixed start (world/spawn) is not free with " + std::to_string(clearance) +
                       " m of clearance (world/start_clearance or the robot's footprint) in " +
                       (map_ ? "world/map" : "the arena"));
    }
    reachFromSpawn();  // goals drawn around it: where the robot can drive
    return;
  }
  reachFromSpawn();
  const double step = map_ ? std::max(map_->resolution, 0.01) : 0.05;
  bool found = false;
  for (double x = region_.min().x(); x <= region_.max().x() && !found; x += step) {
    for (double y = region_.min().y(); y <= region_.max().y() && !found; y += step) {
      found = staticClearance({x, y}) >= clearance && inReach({x, y});
      if (found) fallback_start_ = Eigen::Vector2d(x, y);
    }
  }
  if (!found) {
    throwInvalid("world/start_clearance", config_.start_clearance,
                 std::string("no free point of the region keeps it (and the robot's footprint ") +
                     std::to_string(robot_radius) + " m) from the walls and the map" +
                     (spawn_reach_ ? " where the robot can drive from world/spawn" : ""));
  }
}

void WorldModel::reachFromSpawn() {
  // A map or a Gazebo world's grid reaches past the building (a Gazebo grid 1 m beyond its
  // outermost shape) and holds closed outlines (a refrigerator's four walls): drawn over the whole
  // extent, starts and goals fell outside the walls or inside furniture (issue 48). A region the
  // user gives is drawn in as given.
  if (!map_ || !config_.region.empty()) return;
  const double resolution = std::max(kFootprintGridResolution, map_->resolution);
  auto reach =
      std::make_shared<FootprintGrid>(*this, resolution, robot_radius_, std::vector<Obstacle>());
  const Eigen::Vector2d spawn(config_.spawn[0], config_.spawn[1]);
  if (!reach->reachFrom(spawn)) {
    throwInvalid("world/spawn", listText(config_.spawn),
                 "starts and goals are drawn where the robot can drive from world/spawn, and its "
                 "footprint (" +
                     std::to_string(robot_radius_) + " m) does not fit there: " +
                     (gazebo_ ? gazeboSolidNear(spawn, robot_radius_)
                              : "an occupied, unknown or outside cell of world/map") +
                     "; give a free world/spawn (x_pos, y_pos), or world/region to draw anywhere "
                     "free in it");
  }
  spawn_reach_ = std::move(reach);
}

bool WorldModel::inReach(const Eigen::Vector2d& p) const {
  return !spawn_reach_ || spawn_reach_->reachable(p);
}

void WorldModel::mergeObstacleCells() {
  // Runs of obstacle cells per row, a run merged with the rectangle of the same columns that
  // ended on the row below: a map is a few rectangles, not one box per cell.
  const double r = map_->resolution;
  std::map<std::pair<int, int>, int> open;  // [x0, x1) -> first row
  const auto cell = [&](int x, int y) {
    return obstacle_cells_[static_cast<std::size_t>(y) * map_->width + x] != 0;
  };
  for (int y = 0; y <= map_->height; ++y) {
    std::map<std::pair<int, int>, int> next;
    for (int x = 0; y < map_->height && x < map_->width;) {
      if (!cell(x, y)) {
        ++x;
        continue;
      }
      int x1 = x;
      while (x1 < map_->width && cell(x1, y)) ++x1;
      const auto run = std::make_pair(x, x1);
      const auto it = open.find(run);
      next[run] = it == open.end() ? y : it->second;
      if (it != open.end()) open.erase(it);
      x = x1;
    }
    for (const auto& [run, y0] : open) {
      rectangles_.emplace_back(Eigen::Vector2d(run.first * r, y0 * r),
                               Eigen::Vector2d(run.second * r, y * r));
    }
    open = std::move(next);
  }
}

void WorldModel::computeDistanceField() {
  const int w = map_->width, h = map_->height;
  std::vector<double> squared(static_cast<std::size_t>(w) * h, kFar);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (map_->isObstacle(x, y)) squared[static_cast<std::size_t>(y) * w + x] = 0.0;
    }
  }
  std::vector<double> d, z;
  std::vector<int> v;
  for (int x = 0; x < w; ++x) distanceTransform1d(&squared[x], h, w, d, v, z);
  for (int y = 0; y < h; ++y) {
    distanceTransform1d(&squared[static_cast<std::size_t>(y) * w], w, 1, d, v, z);
  }
  distance_.resize(squared.size());
  for (std::size_t i = 0; i < squared.size(); ++i) {
    distance_[i] = squared[i] >= 0.5 * kFar ? std::numeric_limits<float>::infinity()
                                            : static_cast<float>(std::sqrt(squared[i]));
  }
}

double WorldModel::staticClearance(const Eigen::Vector2d& p) const {
  double clearance = std::numeric_limits<double>::infinity();
  for (const Obstacle& w : walls_) clearance = std::min(clearance, w.distance(p));
  if (map_) {
    int x = 0, y = 0;
    if (!map_->cellOf(p, x, y) || !map_->isFree(x, y)) return 0.0;
    // Cell centre to cell centre, less a cell's diagonal: a lower bound from any point.
    const double cells = distance_[static_cast<std::size_t>(y) * map_->width + x];
    clearance = std::min(clearance, (cells - std::sqrt(2.0)) * map_->resolution);
  }
  return std::max(clearance, 0.0);
}

double WorldModel::clearance(const Eigen::Vector2d& p,
                             const std::vector<Obstacle>* obstacles) const {
  double c = staticClearance(p);
  if (obstacles) {
    for (const Obstacle& o : *obstacles) {
      if (o.placed) c = std::min(c, o.distance(p));
    }
  }
  return c;
}

bool WorldModel::isClear(const Eigen::Vector2d& p, double clearance,
                         const std::vector<Obstacle>& obstacles) const {
  if (staticClearance(p) < clearance) return false;
  for (const Obstacle& o : obstacles) {
    if (o.placed && o.distance(p) < clearance) return false;
  }
  return true;
}

std::optional<Eigen::Vector2d> WorldModel::drawFreePoint(Rng& rng, double clearance) const {
  for (int k = 0; k < config_.placement_tries; ++k) {
    const Eigen::Vector2d p(uniform(rng, region_.min().x(), region_.max().x()),
                            uniform(rng, region_.min().y(), region_.max().y()));
    if (staticClearance(p) >= clearance && inReach(p)) return p;
  }
  return std::nullopt;
}

void WorldModel::drawLayout(Rng& rng, int env, double difficulty, WorldDrawing* task,
                            EnvLayout& layout) const {
  if (!config_.families.empty()) {
    drawGeneratedLayout(*this, rng, env, difficulty, task, layout);
  } else {
    drawStart(rng, layout);
    std::vector<Eigen::Vector2d> keep_free{layout.start};
    WorldDraft draft;
    draft.start = layout.start;
    if (task) task->drawInWorld(env, rng, *this, draft, keep_free);
    drawObstacles(rng, keep_free, layout);
  }
  if (task) task->layoutDrawn(env, *this, layout);
}

void WorldModel::drawStart(Rng& rng, EnvLayout& layout) const {
  layout.start = Eigen::Vector2d(config_.spawn[0], config_.spawn[1]);
  if (!config_.random_start) return;
  // The constructor found a free point: when every draw fails (unlucky in a tight region), that
  // point stands in.
  const auto p = drawFreePoint(rng, start_clearance_);
  layout.start = p ? *p : fallback_start_;
}

void WorldModel::drawObstacles(Rng& rng, const std::vector<Eigen::Vector2d>& keep_free,
                               EnvLayout& layout) const {
  const int boxes = config_.num_boxes, total = boxes + config_.num_cylinders;
  layout.obstacles.resize(total);
  layout.given_up = 0;
  layout.cut_short = false;
  // Every draw is tested against the start, the task's points and the obstacles placed before:
  // a reset does at most kObstacleDrawChecks such tests (issue 49: 2,000 obstacles that do not fit
  // with 100,000 tries each took 18 s a reset).
  std::int64_t checks = 0;
  for (int i = 0; i < total; ++i) {
    Obstacle& o = layout.obstacles[i];
    o.shape = i < boxes ? Obstacle::Shape::kBox : Obstacle::Shape::kCylinder;
    o.height = config_.obstacle_height;
    o.placed = false;
    const std::int64_t tests_per_draw =
        static_cast<std::int64_t>(keep_free.size()) + (config_.allow_overlap ? 0 : i);
    for (int k = 0; k < config_.placement_tries && !o.placed; ++k) {
      if (checks + tests_per_draw > kObstacleDrawChecks) {
        layout.cut_short = true;
        break;
      }
      checks += tests_per_draw;
      if (o.shape == Obstacle::Shape::kBox) {
        o.half_extents =
            0.5 * Eigen::Vector2d(uniform(rng, config_.box_size[0], config_.box_size[1]),
                                  uniform(rng, config_.box_size[0], config_.box_size[1]));
        o.yaw = uniform(rng, -kPi, kPi);
      } else {
        o.radius = uniform(rng, config_.cylinder_radius[0], config_.cylinder_radius[1]);
      }
      o.center = Eigen::Vector2d(uniform(rng, region_.min().x(), region_.max().x()),
                                 uniform(rng, region_.min().y(), region_.max().y()));
      bool fits = true;
      for (const Eigen::Vector2d& p : keep_free) {
        fits = fits && o.distance(p) >= config_.start_clearance;
      }
      for (int j = 0; j < i && fits && !config_.allow_overlap; ++j) {
        const Obstacle& other = layout.obstacles[j];
        fits = !other.placed || (o.center - other.center).norm() >= o.boundingRadius() +
                                                                        other.boundingRadius() +
                                                                        config_.obstacle_gap;
      }
      o.placed = fits;
    }
    if (!o.placed) ++layout.given_up;
  }
}

std::string describeWorld(const WorldModel& world) {
  const WorldConfig& c = world.config();
  std::ostringstream s;
  s << "world:";
  if (const GazeboWorld* g = world.gazebo()) {
    s << " Gazebo world " << g->path << " ('" << g->name << "': " << g->models << " models ("
      << g->plain_models << " plain, " << g->repeated_models << " repeats), " << g->solids.size()
      << " collisions; cut at " << world.cutHeight() << " m: " << world.worldObstacles().size()
      << " upright boxes and cylinders, exact, the rest as " << world.mapRectangles().size()
      << " rectangles of a grid of " << world.map()->width << " x " << world.map()->height
      << " cells of " << world.map()->resolution << " m);";
  }
  if (const OccupancyMap* map = world.gazebo() ? nullptr : world.map()) {
    s << " map " << map->yaml_path << " (" << map->width << " x " << map->height << " cells of "
      << map->resolution << " m, " << enumName(map->mode) << ", " << world.mapRectangles().size()
      << " obstacle rectangles)";
  }
  if (!world.walls().empty())
    s << " arena " << c.arena_size[0] << " x " << c.arena_size[1] << " m;";
  s << " " << c.num_boxes << " boxes and " << c.num_cylinders << " cylinders per env";
  if (!world.region().isEmpty()) {
    s << " in [" << world.region().min().x() << ", " << world.region().min().y() << "] to ["
      << world.region().max().x() << ", " << world.region().max().y() << "] m";
  }
  s << "; start "
    << (c.random_start ? "drawn in free space" : "at world/spawn " + listText(c.spawn))
    << ", clearance " << c.start_clearance << " m";
  return s.str();
}

}  // namespace jetbot_rl
