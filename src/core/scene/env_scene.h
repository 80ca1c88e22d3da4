#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/scene/curriculum.h"
#include "jetbot_rl/world/world_model.h"
#include "scene/moving_bodies.h"
#include "sensors/env_sensor.h"

namespace jetbot_rl {

class EnvPhysics;
class MoverSet;
class PeopleBodies;
class RobotTeam;
class WorldDrawing;
class FloorDrawing;
class WorldShapes;

/**
 * What every env's robots live in, apart from their own physics and the task: the world (map,
 * walls, region) shared by the batch, and per env its layout stream, layout, curriculum level,
 * people (movers) and, with several robots per env, the other robots (RobotTeam). It places a
 * robot for a new episode, steps what moves in its world (MovingBodies) and tells the sensors
 * what there is to see. Rows (robots) are world w K + k; the rows of one world are used from
 * one thread at a time, so that everything is the same on any thread count.
 */
class EnvScene {
 public:
  /// The world of `config` (none when it has none) and its movers; ConfigError from them.
  /// `drawer`, `floor_drawer`: the task's draws at every placing, or none.
  EnvScene(const EnvConfig& config, double robot_radius, WorldDrawing* drawer,
           FloorDrawing* floor_drawer = nullptr);
  ~EnvScene();
  EnvScene(const EnvScene&) = delete;
  EnvScene& operator=(const EnvScene&) = delete;

  /// After the rows' physics were built (`envs`, one per row, kept by the caller): the team,
  /// when configured, with its stand-ins in every row's physics, `robot_height` [m] tall (the
  /// robot's visible top: a scanner above the chassis sees the others' scanners). ConfigError
  /// when its starts do not fit the world.
  void attach(std::vector<std::unique_ptr<EnvPhysics>>& envs, double robot_height);

  /// The world, or nullptr.
  const WorldModel* world() const { return world_.get(); }
  /// The world's static shapes for a row's physics, or nullptr.
  const WorldShapes* shapes() const { return shapes_.get(); }
  /// The movers of every world, or nullptr.
  const MoverSet* movers() const { return movers_.get(); }
  /// The other robots of each world (several robots per env or a circle swap), or nullptr.
  RobotTeam* team() { return team_.get(); }
  const RobotTeam* team() const { return team_.get(); }
  /// Row `row`'s layout of the episode.
  const EnvLayout& layout(int row) const { return layouts_[row]; }
  /// Row `row`'s random stream (layouts, randomisation, the task's draws).
  Rng& rng(int row) { return rngs_[row]; }
  /// Row `row`'s curriculum level, in [0, 1].
  double difficulty(int row) const { return curriculum_.difficulty(row); }
  std::uint64_t obstaclesGivenUp() const { return given_up_; }
  std::uint64_t layoutsUnmade() const { return unmade_; }
  std::uint64_t moversGivenUp() const { return movers_given_up_; }

  /// Before the rows marked in `selected` are reset: robots reset together start free of each
  /// other; a world whose robots are all reset gets its random obstacles anew and its people
  /// anew at endReset() (from its stream restarted at `seed`, when given).
  void beginReset(const std::vector<std::uint8_t>& selected, std::optional<std::uint64_t> seed);
  /// Restarts row `row`'s streams from `seed` (one robot per world: its movers' too).
  void reseed(int row, std::uint64_t seed);
  /// After the robot of row `row` was put at rest (and randomised): its start, the task's draw
  /// (`drawer`), the obstacles, with one robot per world its people, and the task's floor.
  void place(int row);
  /// After the rows of beginReset() were placed: the people of the worlds reset whole.
  void endReset();
  /// Rounds: all robots of world `world` start anew (its random obstacles and people too);
  /// beginRound() before they are placed, endRound() after.
  void beginRound(int world);
  void endRound(int world);
  /// Row `row`'s robot was moved by hand (setRootState): the others see it there.
  void robotMoved(int row);
  /// Counts row `row`'s ended episode for its curriculum.
  void episodeEnded(int row, bool success) { curriculum_.episodeEnded(row, success); }

  /// Once per control step of world `world`, before its robots' physics.
  void beginWorldStep(int world);
  /// What moves in a robot's world: the people, then the other robots.
  const std::vector<MovingBodies*>& moving() const { return moving_; }
  /// What row `row`'s sensors read: its physics, layout, people and other robots.
  SensedEnv sensed(int row) const;

 private:
  /// A row of a world with one robot: its layout, start and people.
  void placeRobot(int row);
  /// A row of a team: its start (and a circle swap's goal) clear of the others of its world and
  /// of its obstacles (drawn first, when anew).
  void placeTeamRobot(int row);
  /// The obstacles (random, or a generated layout) of row `row`'s world, from its stream, for
  /// all its robots.
  void drawWorldObstacles(int row);
  /// Draws the people of world `world` anew, clear of its robots' starts.
  void redrawPeople(int world);

  EnvConfig config_;
  WorldDrawing* drawer_;
  FloorDrawing* floor_drawer_;
  int k_;  // robots per world
  std::vector<std::unique_ptr<EnvPhysics>>* envs_ = nullptr;
  std::shared_ptr<const WorldModel> world_;
  std::unique_ptr<WorldShapes> shapes_;
  std::vector<Rng> rngs_;                    // per row
  std::vector<EnvLayout> layouts_;           // per row
  Curriculum curriculum_;                    // per row
  std::unique_ptr<MoverSet> movers_;         // per world, none without movers
  std::unique_ptr<PeopleBodies> people_;     // the movers as MovingBodies
  std::unique_ptr<RobotTeam> team_;          // with robots_per_env > 1 or a circle swap
  std::vector<MovingBodies*> moving_;        // people_, team_
  std::vector<Eigen::Vector2d> robot_at_;    // per row: its root at its world's step [m]
  std::vector<std::uint8_t> present_;        // per row: in its world at its world's step
  std::vector<std::uint8_t> redraw_people_;  // per world: its people are drawn after its robots
  // A team's random obstacles (world/num_boxes, num_cylinders) or generated layout
  // (world/families) are its world's: drawn anew by the robot placed first when all its robots
  // start anew, kept when one does.
  bool shared_obstacles_ = false;
  bool generated_ = false;                             // world/families
  std::vector<std::uint8_t> redraw_obstacles_;         // per world
  std::vector<std::unique_ptr<FootprintGrid>> grids_;  // per world: its generated layout's
  mutable std::vector<std::vector<Obstacle>> seen_;    // per world: a row's people and robots
  std::atomic<std::uint64_t> given_up_{0};             // obstacles left out
  std::atomic<std::uint64_t> unmade_{0};               // generated layouts not made
  std::atomic<std::uint64_t> movers_given_up_{0};      // movers left out
};

}  // namespace jetbot_rl
