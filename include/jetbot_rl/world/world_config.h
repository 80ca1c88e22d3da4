#pragma once

// Each env's world (docs/world.md): a map_server occupancy map shared by every env, arena walls,
// and random boxes and cylinders placed per env at every reset from the env's own stream. Off by
// default: then an env is the robot alone on an empty plane, bit for bit as without this.

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// The `world/...` parameters (a `world:` block in a parameter file).
struct WorldConfig {
  std::string map;           ///< map_server map YAML; empty: none.
  std::string gazebo_world;  ///< Gazebo SDF world file; empty: none.
  std::string floor;         ///< The camera's floor image YAML; empty: a plain ground.
  double cut_height = 0.0;   ///< Where the Gazebo world is cut for its grid [m]; 0: the scanner's.
  double map_resolution = 0.05;            ///< Cell size of the Gazebo world's grid [m].
  std::vector<double> spawn{0.0, 0.0};     ///< [x, y]: the fixed start, in the env frame [m].
  std::vector<double> arena_size;          ///< [x, y]: walls around each env origin [m]; []: none.
  double wall_thickness = 0.05;            ///< [m]
  double obstacle_height = 0.5;            ///< Of walls, obstacles and map cells [m].
  int num_boxes = 0;                       ///< Random boxes per env.
  std::vector<double> box_size{0.2, 0.5};  ///< [min, max] of each side [m].
  int num_cylinders = 0;                   ///< Random cylinders per env.
  std::vector<double> cylinder_radius{0.1, 0.25};  ///< [min, max] [m].
  /// [x_min, y_min, x_max, y_max] where obstacles and random starts are drawn, in the env frame
  /// [m]; []: inside the arena walls, else the map's extent where the robot can drive from spawn.
  std::vector<double> region;
  double start_clearance = 0.4;  ///< Free radius around the start (and a task's free points) [m].
  double obstacle_gap = 0.0;     ///< Least distance between two obstacles [m].
  bool allow_overlap = false;    ///< Obstacles may overlap each other (obstacle_gap ignored).
  bool random_start = false;     ///< Draw the start in free space at every reset; else the origin.
  int placement_tries = 200;     ///< Draws per start or obstacle before it is given up.
  // ---- generated layouts (world_generation.h) ----
  std::vector<std::string> families;   ///< Families of generated layouts; []: none.
  std::vector<double> family_weights;  ///< How often each family is drawn; []: equally.
  double difficulty = 0.5;             ///< Of generated layouts, in [0, 1] (the start's).
  /// The narrowest passage of generated layouts [robot widths]: [at difficulty 1, at 0].
  std::vector<double> passage_widths{1.5, 4.0};
  int max_generated_obstacles = 400;  ///< Obstacle slots of a generated layout per env.
  bool curriculum = false;            ///< Each env raises its difficulty with its successes.
  int curriculum_episodes = 20;       ///< Episodes an env's success rate is counted over.
  double curriculum_success = 0.8;    ///< The success rate that raises the difficulty.
  double curriculum_step = 0.1;       ///< By this much.
  double curriculum_mix = 0.0;        ///< Share of resets drawn at a difficulty below the env's.
  /// Not a parameter: a Gazebo world's <visual> elements are read too (a camera draws them).
  bool read_visuals = false;
  /// Not a parameter: false for a program that only reads the world (jetbot_rl_world_map): no
  /// start is checked or drawn, and no reach from the spawn kept.
  bool draws = true;

  /// True when the env has any world: a map, walls or obstacles.
  bool enabled() const {
    return !map.empty() || !gazebo_world.empty() || !arena_size.empty() || num_boxes > 0 ||
           num_cylinders > 0 || !families.empty();
  }
  /// The obstacle slots of an env: the random ones and a generated layout's.
  int obstacleSlots() const {
    return num_boxes + num_cylinders + (families.empty() ? 0 : max_generated_obstacles);
  }
};

/// The cut of a world without a scanner to take the height of [m].
constexpr double kDefaultCutHeight = 0.1;

/// The height a Gazebo world is cut at, the one place its default is resolved: world/cut_height
/// when given, else `scanner_height` (the scanner's above the ground; 0: none), else
/// kDefaultCutHeight [m].
inline double resolveCutHeight(const WorldConfig& c, double scanner_height) {
  if (c.cut_height > 0.0) return c.cut_height;
  return scanner_height > 0.0 ? scanner_height : kDefaultCutHeight;
}

template <typename C, typename V>
IfConfig<C, WorldConfig> visitFields(C& c, V&& v) {
  const Range<double> length = positiveUpTo(1000.0, "m");
  v("world/map", c.map, AnyValue{"", "empty: none"},
    "map_server map YAML (image, resolution, origin, negate, occupied_thresh, free_thresh, mode) "
    "placed in every env's frame as map_server places it; its image is read relative to the "
    "YAML.");
  v("world/floor", c.floor, AnyValue{"", "empty: a plain ground"},
    "The camera's floor image: a YAML beside an image (PNG, PGM, JPEG; at most 8192 px a side) "
    "with map_server's image, resolution and origin, laid on the ground of every env's frame as "
    "a map is placed (docs/camera.md); the ground elsewhere keeps its colour. Seen by cameras "
    "only.");
  v("world/gazebo_world", c.gazebo_world, AnyValue{"", "empty: none"},
    "Gazebo SDF world file (.world) read with sdformat: every model's collision geometry at its "
    "initial pose, <include>s resolved through GAZEBO_MODEL_PATH and ROS_PACKAGE_PATH, shared by "
    "every env with the world frame as the env frame. Its upright boxes and cylinders are exact; "
    "other shapes (spheres, meshes, polylines, tilted shapes) enter as the cells of their cut at "
    "cut_height. Not with world/map.");
  v("world/cut_height", c.cut_height,
    Range<double>{0.0, 100.0, false, false, "m", "0: the scanner's height"},
    "Height at which the Gazebo world is cut: solids crossing it are in the world, and its grid "
    "(/map) is their cross-section there. 0: the scanner's height above the ground at rest "
    "(0.1 m for a robot without one).");
  v("world/map_resolution", c.map_resolution, Range<double>{0.005, 1.0, false, false, "m"},
    "Cell size of the Gazebo world's grid (/map, the planner, clearances).");
  v("world/spawn", c.spawn, EachValue<double>{Range<double>{-1e4, 1e4, false, false, "m"}},
    "[x, y]: the fixed start in the env frame when random_start is false (its heading: "
    "initial_yaw), as a Gazebo launch file's x_pos and y_pos. With a map or a Gazebo world and "
    "no region, starts and goals are drawn only where the robot can drive from here (not "
    "outside the building, not inside a closed outline): the robot's footprint must fit here.");
  v("world/arena_size", c.arena_size, EachValue<double>{length},
    "[x, y]: walls of a rectangle this size centred on each env origin; []: none.");
  v("world/wall_thickness", c.wall_thickness, length, "Thickness of the arena walls.");
  v("world/obstacle_height", c.obstacle_height, length,
    "Height of the walls, the obstacles and the map's occupied cells.");
  v("world/num_boxes", c.num_boxes, inRange(0, 1000),
    "Random boxes per env, placed at every reset.");
  v("world/box_size", c.box_size, intervalOf(length),
    "Range of each box's side lengths (drawn per side) and yaw drawn in [-pi, pi).");
  v("world/num_cylinders", c.num_cylinders, inRange(0, 1000),
    "Random cylinders per env, placed at every reset.");
  v("world/cylinder_radius", c.cylinder_radius, intervalOf(length), "Range of their radii.");
  v("world/region", c.region, EachValue<double>{Range<double>{-1e4, 1e4, false, false, "m"}},
    "[x_min, y_min, x_max, y_max] where obstacles and random starts are drawn, in the env frame; "
    "[]: inside the arena walls, else the map's extent where the robot can drive from spawn "
    "(given: anywhere free in it).");
  v("world/start_clearance", c.start_clearance, atLeast(0.0, "m"),
    "No obstacle, wall or occupied cell within this distance of the start, nor of a point a task "
    "keeps free (a goal).");
  v("world/obstacle_gap", c.obstacle_gap, atLeast(0.0, "m"),
    "Least distance between two obstacles' bounding circles.");
  v("world/allow_overlap", c.allow_overlap, AnyValue{}, "Obstacles may overlap each other.");
  v("world/random_start", c.random_start, AnyValue{},
    "Draw each env's start position in free space at every reset (its heading: initial_yaw); "
    "false: the env origin.");
  v("world/placement_tries", c.placement_tries, inRange(1, 100000),
    "Draws for a start or an obstacle before it is given up (an obstacle given up is left out "
    "of that episode and counted); a reset's random obstacles take at most 2e7 placement tests "
    "in all (about 40 ms), and those not placed by then are left out and counted too.");
  v("world/families", c.families, NameList{"", true},
    "Generated layouts, drawn per env at every reset inside the arena: clutter (posts and "
    "crates), rooms (a floor plan with doors), maze or barn (posts grown by a cellular "
    "automaton, as the BARN benchmark's worlds); several: each reset draws one by "
    "family_weights. []: none (the random boxes and cylinders above).");
  v("world/family_weights", c.family_weights, EachValue<double>{atLeast(0.0)},
    "How often each family is drawn (one per family, not all 0); []: equally.");
  v("world/difficulty", c.difficulty, inRange(0.0, 1.0),
    "Of generated layouts: their density, their narrowest passage (passage_widths) and their "
    "rooms' and maze cells' size; with the curriculum, where every env starts.");
  v("world/passage_widths", c.passage_widths,
    intervalOf(Range<double>{1.0, 20.0, true, false, "robot widths"}),
    "[at difficulty 1, at 0]: the narrowest passage generated layouts keep, in robot widths "
    "(twice the footprint radius), from the second at difficulty 0 down to the first at 1 "
    "(between obstacles, doors, maze corridors).");
  v("world/max_generated_obstacles", c.max_generated_obstacles, inRange(1, 100000),
    "Obstacle slots of a generated layout per env (walls included); more are left out and "
    "counted.");
  v("world/curriculum", c.curriculum, AnyValue{},
    "Needs families. Each env raises its own difficulty by curriculum_step (up to 1) after each "
    "run of curriculum_episodes of its episodes in which at least curriculum_success reached "
    "the goal.");
  v("world/curriculum_episodes", c.curriculum_episodes, inRange(1, 100000),
    "The episodes of a run an env's success rate is counted over.");
  v("world/curriculum_success", c.curriculum_success, inRange(0.0, 1.0),
    "The success rate that raises an env's difficulty.");
  v("world/curriculum_step", c.curriculum_step, inRange(0.0, 1.0), "By this much.");
  v("world/curriculum_mix", c.curriculum_mix, inRange(0.0, 1.0),
    "With the curriculum: the share of an env's resets that draw their layout at a difficulty "
    "uniform in [0, the env's] instead of at the env's own, so that easy layouts stay in the "
    "batch; 0: none.");
}

/// The rules between WorldConfig's fields: arena_size has 2 values, region 4 (min < max),
/// obstacles need somewhere to go; generated layouts need an arena, known families, one weight
/// per family, and no random boxes or cylinders besides; the curriculum needs families.
void checkFieldRules(const WorldConfig& config);

}  // namespace jetbot_rl
