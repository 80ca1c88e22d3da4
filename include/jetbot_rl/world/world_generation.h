#pragma once

// Generated worlds (issue 30): each env's layout drawn at every reset from the env's own stream,
// in one of three families, at a difficulty in [0, 1] (docs/world.md#generated-worlds).

#include <Eigen/Geometry>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

class WorldDrawing;

/// Layouts drawn for one reset before it runs in the bare arena (counted as unmade).
constexpr int kLayoutAttempts = 20;

/// The families of generated layouts.
enum class WorldFamily {
  kClutter,  ///< Posts and crates on a jittered grid; denser and narrower with difficulty.
  kRooms,    ///< A floor plan: rooms in a grid, a door in each wall between them, furniture.
  kMaze,     ///< A perfect maze (one way between any two cells) of smaller cells with difficulty.
  kBarn,     ///< BARN's fields: posts grown by a cellular automaton, gaps of 1.05-1.3 widths at 1.
};

inline const EnumNameList<WorldFamily>& enumNames(WorldFamily) {
  static const EnumNameList<WorldFamily> names{{WorldFamily::kClutter, "clutter"},
                                               {WorldFamily::kRooms, "rooms"},
                                               {WorldFamily::kMaze, "maze"},
                                               {WorldFamily::kBarn, "barn"}};
  return names;
}

/// What a family's generator is given: where to build, for which robot, how high.
struct GenerationArea {
  Eigen::AlignedBox2d area;      ///< The floor to fill (inside the arena walls) [m].
  double robot_radius = 0.1;     ///< The robot's footprint [m]: passages keep it through.
  double height = 0.5;           ///< Of the walls and obstacles [m].
  double wall_thickness = 0.05;  ///< Of generated walls [m].
  /// The narrowest passage at difficulty 1 and at 0 [robot widths] (world/passage_widths).
  double passage_widths_hard = 1.5, passage_widths_easy = 4.0;
};

/// The narrowest passage a family leaves at `difficulty` [m]: from passage_widths_easy robot
/// widths at 0 down to passage_widths_hard at 1 (clutter, doors, maze corridors alike).
double narrowestPassage(const GenerationArea& a, double difficulty);

/// Appends to `out` the obstacles (boxes, cylinders; walls as thin boxes) of a layout of
/// `family` at `difficulty`, drawn from `rng`; at most `max_obstacles` of them (the rest are
/// left out, and their count returned).
int generateObstacles(WorldFamily family, double difficulty, const GenerationArea& area, Rng& rng,
                      int max_obstacles, std::vector<Obstacle>& out);

/**
 * Draws env `env`'s generated layout (world/families) at `difficulty` from its stream: a family
 * by world/family_weights, its obstacles in the arena, a start with the start clearance the
 * robot can stand on, then `task`'s goal, which must have a path from the start for the robot's
 * footprint on a FootprintGrid. A layout without such a start and goal is drawn again, up
 * to kLayoutAttempts; then the episode runs in the bare arena and `layout.unmade` is set.
 */
void drawGeneratedLayout(const WorldModel& world, Rng& rng, int env, double difficulty,
                         WorldDrawing* task, EnvLayout& layout);

/// A generated layout for the robots of a team's world (robots_per_env > 1), which draw their
/// own starts and goals in it: a family by world/family_weights and its obstacles at
/// `difficulty`, drawn again (up to kLayoutAttempts) until the robot can start somewhere in it;
/// then the bare arena, with `layout.unmade` set. Returns its footprint grid (nothing reached).
FootprintGrid drawSharedGeneratedLayout(const WorldModel& world, Rng& rng, double difficulty,
                                        EnvLayout& layout);
/// True when a robot of `world` can start at `p` in the layout of `grid` (drawn with
/// `obstacles`): free for its footprint and clear of everything by the start clearance.
bool fitsGeneratedStart(const WorldModel& world, const FootprintGrid& grid,
                        const std::vector<Obstacle>& obstacles, const Eigen::Vector2d& p);

/// Start-up check that every family leaves the robot somewhere to start at world/difficulty and
/// at the hardest the curriculum reaches: ConfigError naming world/difficulty (or
/// world/arena_size) and the family when none of a few trial layouts has a start.
void checkGeneratedLayouts(const WorldModel& world);

}  // namespace jetbot_rl
