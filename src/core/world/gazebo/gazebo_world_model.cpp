// The WorldModel of a Gazebo world (world/gazebo_world): its upright boxes and cylinders stay exact
// obstacles shared by every env; its cut at cut_height is the grid (/map, clearances, planner),
// and the cells of its other shapes are their geometry (collisions and scans, as a map's cells).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {
namespace {

// Free cells around the world's geometry in its grid: room to start beside the outermost solid.
constexpr double kGridMargin = 1.0;  // [m]
// The largest grid a world may cut into (its /map, clearances and planner take about 13 bytes a
// cell: 25 million cells, 0.3 GB, e.g. 250 x 250 m at 0.05 m).
constexpr double kMaxGridCells = 25e6;

}  // namespace

void WorldModel::readGazeboWorld() {
  const std::string& path = config_.gazebo_world;
  auto world = std::make_shared<GazeboWorld>();
  try {
    *world = loadGazeboWorld(path, nullptr, config_.read_visuals);
  } catch (const Error& e) {
    const bool visual =
        config_.read_visuals && std::string(e.what()).find("visual '") != std::string::npos;
    throw ConfigError(std::string("world/gazebo_world: ") + e.what() +
                      (visual ? " (the camera draws the world's visuals; camera/world_visuals: "
                                "false draws the shapes the scanner sees)"
                              : ""));
  }
  const double height = cutHeight(), resolution = config_.map_resolution;
  const Eigen::AlignedBox2d area = cutArea(world->solids, height, resolution, kGridMargin);
  if (area.isEmpty()) {
    throwInvalid("world/gazebo_world", path,
                 "none of its " + std::to_string(world->solids.size()) +
                     " collisions crosses the cut at " + std::to_string(height) +
                     " m (world/cut_height): the world would be empty");
  }
  const double cells =
      std::ceil(area.sizes().x() / resolution) * std::ceil(area.sizes().y() / resolution);
  if (!(cells <= kMaxGridCells)) {
    // Name the collision that reaches farthest from the origin: what makes the grid this large.
    const WorldSolid* far = nullptr;
    double reach = -1.0;
    for (const WorldSolid& s : world->solids) {
      if (!crossesHeight(s, height)) continue;
      const double r =
          std::max(s.bounds.min().cwiseAbs().maxCoeff(), s.bounds.max().cwiseAbs().maxCoeff());
      if (r > reach) reach = r, far = &s;
    }
    std::ostringstream why;
    why << "its collisions span " << area.sizes().x() << " x " << area.sizes().y()
        << " m: " << cells << " cells of world/map_resolution " << resolution
        << " m, more than the " << kMaxGridCells << " its grid may hold"
        << (far ? "; the farthest from the origin is '" + far->name + "'" : std::string());
    throwInvalid("world/gazebo_world", path, why.str());
  }
  map_ = cutSolids(world->solids, height, resolution, area, SolidKinds::kAll);
  map_->yaml_path = path;
  const OccupancyMap others =
      cutSolids(world->solids, height, resolution, area, SolidKinds::kOthers);
  obstacle_cells_.resize(others.data.size());
  for (std::size_t i = 0; i < others.data.size(); ++i) obstacle_cells_[i] = others.data[i] != 0;
  for (const WorldSolid& s : world->solids) {
    if (s.upright && crossesHeight(s, height)) world_obstacles_.push_back(*s.upright);
  }
  gazebo_ = std::move(world);
}

std::string WorldModel::gazeboSolidNear(const Eigen::Vector2d& p, double reach) const {
  std::string names;
  int n = 0;
  for (const WorldSolid& s : gazebo_->solids) {
    if (!crossesHeight(s, cutHeight())) continue;
    const double d = s.upright ? s.upright->distance(p) : s.bounds.exteriorDistance(p);
    if (d >= reach) continue;
    if (n++ < 3) names += (names.empty() ? "'" : ", '") + s.name + "'";
  }
  if (n == 0) return "near the edge of " + gazebo_->path + "'s grid";
  return std::string(n > 3 ? "near " + std::to_string(n) + " collisions, first "
                           : "inside or near ") +
         names + " of " + gazebo_->path;
}

}  // namespace jetbot_rl
