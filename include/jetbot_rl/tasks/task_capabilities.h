#pragma once

// What only some tasks do. A task opts in by deriving from the capability as well as from Task;
// the code that serves it asks for it with capability<C>(task) (task.h).

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/rng.h"

namespace jetbot_rl {

class WorldModel;
struct WorldDraft;
struct EnvLayout;
struct FloorImage;
struct RootState;

/// A task with a command a user can set per env (served by the env node's ~set_command).
class Commandable {
 public:
  virtual ~Commandable() = default;
  /// Size of the command (SetCommand's x, y).
  virtual int commandDim() const = 0;
  /// Sets env `env`'s command (`commandDim()` values), kept across its resets when `hold`;
  /// throws InputError naming the env and value when invalid.
  virtual void setCommand(int env, const std::vector<double>& command, bool hold) = 0;
};

/// A task that places something in an env's world at each reset (a goal kept free of obstacles).
class WorldDrawing {
 public:
  virtual ~WorldDrawing() = default;
  /// At a reset of an env with a world, after its start was drawn (and a generated layout's
  /// obstacles placed): draws what the task keeps free of obstacles from `rng` and appends its
  /// points to `keep_free`. False when no draw kept its clearance or, with `draft.reach`, had a
  /// path from the start (a generated layout is then drawn again).
  virtual bool drawInWorld(int env, Rng& rng, const WorldModel& world, const WorldDraft& draft,
                           std::vector<Eigen::Vector2d>& keep_free) = 0;
  /// After env `env`'s layout is complete (its obstacles placed): what the task derives from it
  /// (the navigation task's path). Draws nothing from the stream.
  virtual void layoutDrawn(int env, const WorldModel& world, const EnvLayout& layout) {
    (void)env, (void)world, (void)layout;
  }
};

/// A task that paints the floor of each episode (road following's tape), with or without a world.
class FloorDrawing {
 public:
  virtual ~FloorDrawing() = default;
  /// At every reset of env `env`, once its robot stands at `start` (env frame): draws the floor
  /// of its new episode about it from `rng`; what the camera sees on the ground instead of the
  /// world's floor (the env's layout and its camera scene hold it while they show it).
  virtual std::shared_ptr<const FloorImage> drawFloor(int env, Rng& rng,
                                                      const RootState& start) = 0;
};

/// A task with directions worth drawing per env besides the robot's forward arrow (markers).
class ArrowDrawing {
 public:
  virtual ~ArrowDrawing() = default;
  /// Names of the directions (marker namespaces), one per arrowDirection() index.
  virtual std::vector<std::string> arrowNames() const = 0;
  /// Unit direction `arrow` of env `env` in the env frame's ground plane.
  virtual Eigen::Vector2d arrowDirection(int env, int arrow) const = 0;
};

}  // namespace jetbot_rl
