#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/world/occupancy_map.h"
#include "jetbot_rl/world/world_config.h"

namespace jetbot_rl {

class WorldDrawing;
class FootprintGrid;
struct FloorImage;
struct GazeboWorld;

/// A box or a vertical cylinder standing on the ground, in an env's frame.
struct Obstacle {
  enum class Shape { kBox, kCylinder };
  Shape shape = Shape::kBox;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();        ///< [m]
  double yaw = 0.0;                                        ///< Box: about z [rad].
  Eigen::Vector2d half_extents = Eigen::Vector2d::Zero();  ///< Box: half its sides [m].
  double radius = 0.0;                                     ///< Cylinder [m].
  double height = 0.0;                                     ///< [m]
  bool placed = true;  ///< false: given up at this reset (not in the world).

  /// Radius of its bounding circle about `center` [m].
  double boundingRadius() const { return shape == Shape::kBox ? half_extents.norm() : radius; }
  /// Distance from `p` to its outline, negative inside [m].
  double distance(const Eigen::Vector2d& p) const;
};

/// The most placement tests (a drawn obstacle against the start, a point the task keeps free or
/// an obstacle placed before) one reset's random obstacles may take: about 40 ms here.
constexpr std::int64_t kObstacleDrawChecks = 20'000'000;

/// One env's layout, drawn at a reset: where the robot starts and its obstacles.
struct EnvLayout {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< Root link origin at the start [m].
  /// num_boxes boxes, then the cylinders; or a generated layout's obstacles and walls.
  std::vector<Obstacle> obstacles;
  int given_up = 0;  ///< Obstacles left out at this reset.
  /// The draw spent kObstacleDrawChecks before placing every obstacle: those not placed by then
  /// are left out (counted in given_up).
  bool cut_short = false;
  int family = -1;          ///< Generated: the index of its family in world/families; else -1.
  double difficulty = 0.0;  ///< Generated: the difficulty it was made at, in [0, 1].
  /// Generated: no layout with a start and a reachable goal was made in kLayoutAttempts; the
  /// episode runs in the bare arena instead (counted, see BatchedEnv::layoutsUnmade()).
  bool unmade = false;
  /// The floor a task painted for the episode (FloorDrawing: road following's tape), or none:
  /// the world's.
  std::shared_ptr<const FloorImage> floor;
};

/// What a task draws its points into at a reset: the start, the obstacles already placed (a
/// generated layout's; none before random obstacles) and, for a generated layout, the cells the
/// robot can reach from the start.
struct WorldDraft {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();   ///< [m]
  const std::vector<Obstacle>* obstacles = nullptr;  ///< null: none yet.
  const FootprintGrid* reach = nullptr;              ///< null: no path check.
  std::optional<Eigen::Vector2d> goal;  ///< A goal the world gives (a circle swap's) [m].
};

/**
 * What every env's world shares, read only (one model, per-env state, as the robot): the map,
 * its obstacle cells merged into rectangles, the arena walls, the region where starts and
 * obstacles are drawn, and a distance field for free-space queries. Draws each env's layout from
 * the env's own stream.
 */
class WorldModel {
 public:
  /// Loads the map (ConfigError naming the map's field or file) and checks that a start fits:
  /// ConfigError naming world/start_clearance (or world/map, world/region) when no free point
  /// has the clearance. `robot_radius` [m]: the robot's footprint. `config` is valid
  /// (validateConfig() at the boundary: the env's EnvConfig::validate(), a program's options).
  WorldModel(const WorldConfig& config, double robot_radius);
  /// The same with a map already loaded (a robot's /map) in place of world/map's file.
  WorldModel(const WorldConfig& config, double robot_radius, const OccupancyMap& map);

  const WorldConfig& config() const { return config_; }
  /// The map, if one is loaded.
  const OccupancyMap* map() const { return map_ ? &*map_ : nullptr; }
  /// The map's frame in the env frame (its origin: the lower-left cell's corner).
  const Eigen::Isometry2d& mapPose() const { return map_pose_; }
  /// The map's obstacle cells merged into rectangles, in the map frame [m].
  const std::vector<Eigen::AlignedBox2d>& mapRectangles() const { return rectangles_; }
  /// Per map cell (OccupancyGrid order): 1 for an obstacle cell (OccupancyMap::isObstacle); for
  /// a Gazebo world's grid, the cells of its shapes that are not worldObstacles().
  const std::vector<std::uint8_t>& obstacleCells() const { return obstacle_cells_; }
  /// True when some obstacleCells() is 1 (scans march through the grid only then).
  bool hasObstacleCells() const { return !rectangles_.empty(); }
  /// The arena walls (boxes), in the env frame.
  const std::vector<Obstacle>& walls() const { return walls_; }
  /// The Gazebo world's upright boxes and cylinders that cross the cut (exact; the other shapes
  /// are obstacleCells()), in the env frame.
  const std::vector<Obstacle>& worldObstacles() const { return world_obstacles_; }
  /// The Gazebo world as read (world/gazebo_world), or null.
  const GazeboWorld* gazebo() const { return gazebo_.get(); }
  /// The height the Gazebo world is cut at: world/cut_height, or kDefaultCutHeight when it is 0
  /// (the env resolves 0 to its scanner's height before building the world) [m].
  double cutHeight() const { return resolveCutHeight(config_, 0.0); }
  /// Where starts and obstacles are drawn, in the env frame (an empty box when unbounded).
  const Eigen::AlignedBox2d& region() const { return region_; }

  /// Distance from `p` (env frame) to the nearest wall or map obstacle cell, a lower bound
  /// within one cell's diagonal; 0 on a map cell that is not free or outside the map [m].
  double staticClearance(const Eigen::Vector2d& p) const;
  /// Distance from `p` to the walls, the map and every placed obstacle of `obstacles` [m].
  double clearance(const Eigen::Vector2d& p, const std::vector<Obstacle>* obstacles) const;
  /// True when `p` keeps `clearance` from the walls and the map and from every placed obstacle.
  bool isClear(const Eigen::Vector2d& p, double clearance,
               const std::vector<Obstacle>& obstacles) const;
  /// A point drawn uniformly in the region that keeps `clearance` from the static world and is
  /// inReach(), from `rng`; std::nullopt after world/placement_tries draws.
  std::optional<Eigen::Vector2d> drawFreePoint(Rng& rng, double clearance) const;
  /// True when the robot can drive to `p` from world/spawn, or when no reach is kept (see
  /// spawnReach()).
  bool inReach(const Eigen::Vector2d& p) const;
  /// With a map or a Gazebo world and no world/region: the free space the robot's footprint can
  /// reach from world/spawn, where starts and goals are drawn (not outside a building, not inside
  /// a closed outline); else null (the region is drawn in).
  const FootprintGrid* spawnReach() const { return spawn_reach_.get(); }

  /// Draws the start (random_start: in free space with start_clearance, at least the robot's
  /// footprint; else the origin).
  void drawStart(Rng& rng, EnvLayout& layout) const;
  /// Draws the obstacles, none within start_clearance of `keep_free` (the start and any point a
  /// task keeps free), none overlapping another unless allowed. An obstacle that does not fit
  /// in placement_tries draws is left out (placed false) and counted in layout.given_up.
  void drawObstacles(Rng& rng, const std::vector<Eigen::Vector2d>& keep_free,
                     EnvLayout& layout) const;
  /// Draws env `env`'s layout of a new episode from its stream `rng`: the start, then what
  /// `task` keeps free of obstacles (a goal; nothing without a task), then the obstacles. With
  /// world/families, a generated layout at `difficulty` (drawGeneratedLayout()).
  void drawLayout(Rng& rng, int env, double difficulty, WorldDrawing* task,
                  EnvLayout& layout) const;
  /// The robot's footprint radius [m].
  double robotRadius() const { return robot_radius_; }
  /// The clearance a start keeps: world/start_clearance, at least the robot's footprint [m].
  double startClearance() const { return start_clearance_; }

 private:
  WorldModel(const WorldConfig& config, double robot_radius, const OccupancyMap* loaded);
  void mergeObstacleCells();
  void computeDistanceField();
  /// Reads world/gazebo_world: the grid cut from it (map_), its other shapes' cells and its
  /// upright solids (world_obstacles_). ConfigError naming world/gazebo_world.
  void readGazeboWorld();
  /// "inside or near <the Gazebo solids within `reach` of p>", for a refused spawn.
  std::string gazeboSolidNear(const Eigen::Vector2d& p, double reach) const;
  /// Marks spawn_reach_ (a map or a Gazebo world, no world/region); ConfigError naming
  /// world/spawn when the robot's footprint does not fit there.
  void reachFromSpawn();

  WorldConfig config_;
  std::optional<OccupancyMap> map_;
  Eigen::Isometry2d map_pose_ = Eigen::Isometry2d::Identity();
  std::vector<Eigen::AlignedBox2d> rectangles_;
  std::vector<Obstacle> walls_;
  std::shared_ptr<const GazeboWorld> gazebo_;
  std::vector<Obstacle> world_obstacles_;
  Eigen::AlignedBox2d region_;
  std::vector<std::uint8_t> obstacle_cells_;
  std::vector<float> distance_;   // per map cell: to the nearest obstacle cell's centre [cells]
  double start_clearance_ = 0.0;  // start_clearance, at least the robot's footprint [m]
  double robot_radius_ = 0.0;
  Eigen::Vector2d fallback_start_ = Eigen::Vector2d::Zero();  // a free start, found at start-up
  std::shared_ptr<const FootprintGrid> spawn_reach_;          // see spawnReach()
};

using WorldModelConstPtr = std::shared_ptr<const WorldModel>;

/// One line for the start-up echo: the map (size, resolution, rectangles), walls, obstacles,
/// region and start.
std::string describeWorld(const WorldModel& world);

}  // namespace jetbot_rl
