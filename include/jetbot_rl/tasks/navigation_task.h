#pragma once

#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/planning/path_tracker.h"
#include "jetbot_rl/tasks/observer_spec.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/// The navigation task's parameters (`nav/...`).
struct NavigationConfig {
  int beams = 24;                               ///< Beams taken from the scan, evenly spread.
  std::vector<double> goal_distance{1.0, 3.0};  ///< [min, max] from the start [m].
  double goal_clearance = 0.3;       ///< Free radius around the goal: walls, map, obstacles [m].
  double goal_radius = 0.2;          ///< Reached within this of the root link origin [m].
  double progress_reward = 10.0;     ///< Per metre of progress towards the goal.
  double goal_reward = 10.0;         ///< On reaching it.
  double collision_penalty = 10.0;   ///< On a collision.
  double step_cost = 0.01;           ///< Per control step.
  double proximity_distance = 0.25;  ///< Closer than this, a scan range costs [m].
  double proximity_penalty = 0.1;  ///< Per step at range 0, falling linearly to 0 at the distance.
  bool goal_reachable = false;     ///< Goals only where the robot can drive from the start.
  bool log_beams = false;          ///< Beams on a log scale of range (finer near the robot).
  bool path = false;               ///< Plan a path to the goal and observe and follow it.
  double path_lookahead = 0.6;     ///< The observed point this far along the path [m].
  double path_clearance = 0.3;  ///< Paths keep this beyond the footprint where there is room [m].
  double path_clearance_cost = 2.0;  ///< The cost of a cell at the footprint, per cell length.
};

template <typename C, typename V>
IfConfig<C, NavigationConfig> visitFields(C& c, V&& v) {
  v("nav/beams", c.beams, inRange(1, 100000),
    "Beams of the observation, read from the whole scan: beam i is the smallest reading of "
    "samples [i x samples / beams, (i + 1) x samples / beams), so that nothing between two beams "
    "is lost; divided by range_max (+inf as 1, -inf as range_min / range_max).");
  v("nav/log_beams", c.log_beams, AnyValue{},
    "Observe each beam as log(range / range_min) / log(range_max / range_min), in [0, 1], named "
    "beam_log_<i>, instead of range / range_max: 0.05 m at 0.15 m moves it as much as 0.33 m at "
    "1 m does, so that the policy tells a wall at 0.15 m from one at 0.2 m.");
  v("nav/goal_distance", c.goal_distance, intervalOf(positiveUpTo(1000.0, "m")),
    "Range of the goal's distance from the start, drawn at every reset (its direction uniform).");
  v("nav/goal_clearance", c.goal_clearance, atLeast(0.0, "m"),
    "No wall, map obstacle cell or obstacle within this of the goal (obstacles keep "
    "world/start_clearance from it too).");
  v("nav/goal_radius", c.goal_radius, positiveUpTo(100.0, "m"),
    "The goal is reached (success, terminated) within this of the robot's root link origin.");
  v("nav/progress_reward", c.progress_reward, atLeast(0.0, "1/m"),
    "progress variant: reward per metre the robot got closer to the goal in a step.");
  v("nav/goal_reward", c.goal_reward, atLeast(0.0), "Reward on reaching the goal.");
  v("nav/collision_penalty", c.collision_penalty, atLeast(0.0),
    "Penalty on a collision with the world (terminated, outcome collision).");
  v("nav/step_cost", c.step_cost, atLeast(0.0), "Cost of every control step.");
  v("nav/proximity_distance", c.proximity_distance, atLeast(0.0, "m"),
    "A scan range below this costs (the robot keeps off obstacles before it touches them).");
  v("nav/proximity_penalty", c.proximity_penalty, atLeast(0.0),
    "Per step: this x (1 - closest range / proximity_distance) when the closest range of the scan "
    "is below proximity_distance.");
  v("nav/goal_reachable", c.goal_reachable, AnyValue{},
    "Goals are redrawn until the robot can drive to them from the start in the world's walls and "
    "map (a path for its footprint on 0.05 m cells): goals anywhere in a map, other rooms "
    "included. Generated worlds always check (against their obstacles too).");
  v("nav/path", c.path, AnyValue{},
    "A global path: at every reset the cheapest path from the start to the goal is planned on the "
    "env's layout inflated by the robot's footprint (A*, 0.05 m cells); the robot observes what "
    "is left of it and the direction of a point path_lookahead along it, and the progress "
    "variant rewards progress along it. Needs a world.");
  v("nav/path_lookahead", c.path_lookahead, positiveUpTo(100.0, "m"),
    "The observed point's distance along the path past the robot's nearest point of it.");
  v("nav/path_clearance", c.path_clearance, atLeast(0.0, "m"),
    "The clearance beyond the footprint a path keeps from walls and obstacles where there is "
    "room: a cell nearer costs more (costmap_2d's inflation, linear).");
  v("nav/path_clearance_cost", c.path_clearance_cost, atLeast(0.0),
    "What a cell at the footprint costs beyond its length, per cell length (0 at path_clearance).");
}

/// Sets what of `config` the observation contract `spec` fixes (a policy trained on it observes
/// that way): beams, log_beams, goal_radius, path and its look-ahead, clearance and cost.
void takeObservationContract(const ObserverSpec& spec, NavigationConfig& config);

/**
 * The navigation task's observation: K scan beams (each clamped into [range_min, range_max] and
 * divided by range_max), the goal's distance and direction (cos, sin) in the robot frame, the
 * forward speed, the yaw rate and the last action; the goal is reached within goal_radius of the
 * root link origin.
 */
class NavigationObserver : public TaskObserver {
 public:
  /// `beams` beams of a scanner reading [range_min, range_max] [m]; `action_dim` last actions;
  /// `log_beams`: beams on a log scale (nav/log_beams).
  NavigationObserver(int beams, double range_min, double range_max, int action_dim,
                     double goal_radius, bool path = false, bool log_beams = false);
  /// The observer of an observation contract (its beams, range, scale, goal radius, path) with
  /// `action_dim` last actions; ConfigError without beams or with an invalid range.
  NavigationObserver(const ObserverSpec& spec, int action_dim);

  std::vector<std::string> observationNames() const override;
  void observationBounds(std::vector<float>& low, std::vector<float>& high) const override;
  int scanBeams() const override { return beams_; }
  bool hasGoal() const override { return true; }
  void observe(const MeasuredState& state, float* obs) const override;
  bool reached(const MeasuredState& state) const override;

  /// A reading as the observation holds it: NaN and +inf as range_max, -inf as range_min,
  /// clamped into [range_min, range_max], divided by range_max (or on a log scale, log_beams).
  float beamValue(float range) const;
  int actionDim() const { return action_dim_; }

 private:
  int beams_, action_dim_;
  float range_min_, range_max_;
  double goal_radius_;
  bool path_, log_beams_;
  float log_span_;  // log(range_max / range_min)
};

/**
 * Goal-reaching without hitting anything (docs/navigation.md): at every reset each env draws a
 * goal (distance range from the start, clearance from the world, from its stream); the robot
 * observes K beams of its laser scan, the goal in its own frame, its forward speed and yaw rate
 * and its last action (NavigationObserver); it is rewarded for progress towards the goal (variant
 * progress) or only for the outcome (sparse), plus goal_reward on reaching it, minus
 * collision_penalty on a collision and step_cost per step; reaching the goal or colliding
 * terminates the episode. Needs a laser scanner.
 */
class NavigationTask : public Task, public WorldDrawing, public ArrowDrawing {
 public:
  enum class Variant { kProgress, kSparse };

  /// `config` is valid (makeTask() validates its TaskConfig).
  explicit NavigationTask(const NavigationConfig& config = NavigationConfig(),
                          Variant variant = Variant::kProgress);

  std::string name() const override { return "navigation"; }
  const TaskObserver& observer() const override { return observer_; }
  void attach(const TaskContext& context) override;
  void resize(int num_envs) override;
  bool drawInWorld(int env, Rng& rng, const WorldModel& world, const WorldDraft& draft,
                   std::vector<Eigen::Vector2d>& keep_free) override;
  void layoutDrawn(int env, const WorldModel& world, const EnvLayout& layout) override;
  void resetEnv(int env, Rng& rng) override;
  void sense(int env, const EnvSenses& senses) override;
  void observe(int env, const RootState& state, float* obs) const override;
  float reward(int env, const RootState& state) const override;
  bool terminated(int env, const RootState& state) const override;
  Outcome outcome(int env) const override { return static_cast<Outcome>(outcome_.at(env)); }
  std::vector<std::string> arrowNames() const override;
  void describeObservation(ObserverSpec& spec) const override;
  Eigen::Vector2d arrowDirection(int env, int arrow) const override;

  /// Env `env`'s path to its goal (nav/path): the start, where it turns, the goal [m]; without
  /// one planned, the start and the goal.
  const std::vector<Eigen::Vector2d>& path(int env) const { return trackers_.at(env).points(); }
  /// Resets since construction whose path could not be planned (the straight line stood in).
  std::uint64_t pathsUnplanned() const { return unplanned_; }
  /// Env `env`'s goal in the env frame [m].
  const Eigen::Vector2d& goal(int env) const { return goals_.at(env); }
  /// Sets env `env`'s goal (a tool or test), keeping its progress reference.
  void setGoal(int env, const Eigen::Vector2d& goal);
  const NavigationConfig& config() const { return config_; }
  Variant variant() const { return variant_; }

 private:
  double distance(int env, const RootState& state) const;
  bool drawGoalAround(int env, Rng& rng, const Eigen::Vector2d& start, const WorldModel* world,
                      const WorldDraft* draft);

  NavigationConfig config_;
  Variant variant_;
  TaskContext context_;
  NavigationObserver observer_;         // its scanner's range once attached
  std::vector<double> beam_angles_;     // per observation beam: its sector's start [rad]
  double beam_width_ = 0.0;             // each sector's width [rad]
  double scan_increment_ = 0.0;         // the scanner's sample spacing [rad]
  std::vector<Eigen::Vector2d> goals_;  // per env
  std::vector<unsigned char> drawn_;    // per env: the goal was drawn in the world at this reset
  std::vector<EnvSenses> senses_;       // per env
  mutable std::vector<double> last_distance_;      // per env: to the goal after the last step
  mutable std::vector<unsigned char> outcome_;     // per env: of the episode that ended
  mutable std::vector<PathTracker> trackers_;      // per env: along its path (nav/path)
  std::atomic<std::uint64_t> unplanned_{0};        // paths not planned
  mutable std::vector<Eigen::Vector2d> position_;  // per env: last observed root position
};

inline const EnumNameList<NavigationTask::Variant>& enumNames(NavigationTask::Variant) {
  static const EnumNameList<NavigationTask::Variant> names{
      {NavigationTask::Variant::kProgress, "progress"},
      {NavigationTask::Variant::kSparse, "sparse"}};
  return names;
}

}  // namespace jetbot_rl
