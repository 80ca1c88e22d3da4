#pragma once

// A Gazebo world as its SDF file describes it (docs/world.md, "Gazebo worlds"): the collision
// and visual geometry of every model, read with sdformat, placed in the world frame.

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/world/gazebo/mesh_loader.h"
#include "jetbot_rl/world/occupancy_map.h"
#include "jetbot_rl/world/texture_image.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// One `<collision>` of a Gazebo world, in the world frame.
struct WorldSolid {
  std::string name;  ///< Scoped as Gazebo scopes it: model::nested::link::collision.
  /// A box or cylinder standing upright (an axis along z): exact, as an obstacle from the ground
  /// up to its top. Empty for any other shape.
  std::optional<Obstacle> upright;
  /// Any other shape's surface: three corners per triangle [m]. Empty for an upright one.
  std::vector<Eigen::Vector3d> triangles;
  double bottom = 0.0, top = 0.0;  ///< Its lowest and highest point [m].
  Eigen::AlignedBox2d bounds;      ///< Its extent in the ground plane [m].
};

/// One `<visual>` of a Gazebo world, in the world frame: what a camera sees of it.
struct WorldVisual {
  std::string name;  ///< Scoped as Gazebo scopes it: model::nested::link::visual.
  std::vector<Eigen::Vector3d> triangles;  ///< Three corners per triangle [m].
  /// Diffuse RGB in [0, 1]: its `<material>`'s `<diffuse>`, else its Gazebo script's colour
  /// (Gazebo/Grey, Gazebo/Wood, ...), else its mesh's own material's, else grey.
  Eigen::Vector3f colour{0.7f, 0.7f, 0.7f};
  /// Without a `<material>`, its mesh material's diffuse texture (drawn instead of `colour`), or
  /// nullptr. One image per file, shared.
  std::shared_ptr<const TextureImage> texture;
  std::vector<Eigen::Vector2f> uv;  ///< With `texture`: texture coordinates per corner.
};

/// A Gazebo world's collision geometry and what was not read of it.
struct GazeboWorld {
  std::string path;                  ///< The file as given.
  std::string name;                  ///< The `<world name>`.
  std::vector<WorldSolid> solids;    ///< Every model's collisions, at the models' initial poses.
  std::vector<WorldVisual> visuals;  ///< Every model's visuals, likewise.
  int models = 0;                    ///< Models read, nested ones included.
  /// Of the world's top-level models: those read without sdformat (plain ones: links of boxes,
  /// cylinders and spheres at plain poses), and those that repeat an earlier one but for their
  /// name and pose (its shapes moved). sdformat copies a model's description per model read.
  int plain_models = 0, repeated_models = 0;
  /// What was not read, for one INFO line (lights, plugins, planes, ...); "" when nothing.
  std::string skipped;
  /// Links whose inertia sdformat refuses and Gazebo 11 loads (collision shapes need none),
  /// read without it: one line each naming the file, line, model and link, for a WARN each.
  std::vector<std::string> warnings;
};

/**
 * Reads the SDF world file at `path` with sdformat: every model's (static or not, nested or
 * included) collision shapes, posed through models, links and collisions as SDF defines
 * (`relative_to`, frames). Boxes, cylinders, spheres, ellipsoids, capsules, meshes (assimp, with
 * `<scale>`; URIs `model://`, `file://`, relative to their SDF file, or through `resolver`) and
 * `<polyline>` extrusions; planes (the ground) and heightmaps are skipped and named in `skipped`.
 * With `visuals`, every `<visual>` too (GazeboWorld::visuals: the same shapes, with their
 * materials' colours). Throws ConfigError naming the file and line as sdformat reports them, the
 * mesh that cannot be read or the model URI that cannot be found. A link whose inertia sdformat
 * refuses (a zero or repeated moment: Gazebo 11 loads it) is read without it, and named in
 * GazeboWorld::warnings.
 */
GazeboWorld loadGazeboWorld(const std::string& path, const MeshResolver& resolver = nullptr,
                            bool visuals = false);

/// True when the solid crosses the plane z = `height` [m].
bool crossesHeight(const WorldSolid& solid, double height);

/**
 * The solids crossing z = `height` cut by that plane into an occupancy grid of `resolution` [m]
 * over `area` (cells: 100 occupied, 0 free; origin: area's corner): a cell is occupied when the
 * cross-section touches it. Only the upright solids, or only the others, with `which`.
 */
enum class SolidKinds { kAll, kUpright, kOthers };
OccupancyMap cutSolids(const std::vector<WorldSolid>& solids, double height, double resolution,
                       const Eigen::AlignedBox2d& area, SolidKinds which = SolidKinds::kAll);

/// The ground-plane extent of the solids crossing z = `height`, grown by `margin` and snapped
/// outwards to multiples of `resolution` [m]; empty when none crosses.
Eigen::AlignedBox2d cutArea(const std::vector<WorldSolid>& solids, double height, double resolution,
                            double margin);

}  // namespace jetbot_rl
