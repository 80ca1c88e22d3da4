#pragma once

// Moving obstacles (docs/world.md, "Moving obstacles"): people (cylinders) and carts (boxes) that
// walk between waypoints in each env's world, drawn per env from its own stream. Off by default.

#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// How a mover heads for its waypoint.
enum class MoverRule {
  kStraight,     ///< Straight at its speed, blind to the others and the robot.
  kSocialForce,  ///< Helbing's social force: drawn to its waypoint, pushed off the others.
};

inline const EnumNameList<MoverRule>& enumNames(MoverRule) {
  static const EnumNameList<MoverRule> names{{MoverRule::kStraight, "straight"},
                                             {MoverRule::kSocialForce, "social_force"}};
  return names;
}

/// The `movers/...` parameters (a `movers:` block in a parameter file).
struct MoverConfig {
  int num_people = 0;                             ///< Cylinders per env.
  std::vector<double> person_radius{0.15, 0.25};  ///< [min, max] [m].
  int num_carts = 0;                              ///< Boxes per env.
  std::vector<double> cart_size{0.3, 0.6};        ///< [min, max] of each side [m].
  std::vector<double> speed{0.3, 1.0};            ///< [min, max], drawn per mover [m/s].
  double height = 1.7;                            ///< Of every mover [m].
  MoverRule rule = MoverRule::kSocialForce;       ///< How they walk.
  bool avoid_robot = true;                        ///< The social force pushes off the robot.
  double start_clearance = 0.8;                   ///< Free radius around the robot's start [m].
  /// [x_min, y_min, x_max, y_max] where they start and head, in the env frame [m]; []: the world's.
  std::vector<double> region;
  double social_strength = 10.0;  ///< A: the force at contact [m/s^2].
  double social_range = 0.2;      ///< B: its fall-off length [m].
  double relaxation_time = 0.5;   ///< tau: to regain its speed [s].

  int count() const { return num_people + num_carts; }
};

template <typename C, typename V>
IfConfig<C, MoverConfig> visitFields(C& c, V&& v) {
  const Range<double> length = positiveUpTo(100.0, "m");
  v("movers/num_people", c.num_people, inRange(0, 1000),
    "People per env: vertical cylinders walking between waypoints. Needs a world.");
  v("movers/person_radius", c.person_radius, intervalOf(length), "Range of their radii.");
  v("movers/num_carts", c.num_carts, inRange(0, 1000),
    "Carts per env: boxes moving between waypoints, turned to where they go. Needs a world.");
  v("movers/cart_size", c.cart_size, intervalOf(length),
    "Range of each cart's side lengths (drawn per side).");
  v("movers/speed", c.speed, intervalOf(positiveUpTo(10.0, "m/s")),
    "Range of a mover's walking speed, drawn per mover at every reset.");
  v("movers/height", c.height, length, "Height of every mover.");
  v("movers/rule", c.rule, AnyValue{},
    "straight: each heads straight for its waypoint at its speed, through the others, blind to "
    "the robot; social_force: Helbing and Molnar's social force model (docs/world.md): drawn to "
    "its waypoint at its speed, pushed off the other movers, the world's obstacles and (with "
    "avoid_robot) the robot.");
  v("movers/avoid_robot", c.avoid_robot, AnyValue{},
    "With social_force: the robot pushes the movers off as another mover does; false: they do "
    "not see it (CrowdNav's invisible robot).");
  v("movers/start_clearance", c.start_clearance, atLeast(0.0, "m"),
    "No mover starts within this of the robot's start.");
  v("movers/region", c.region, EachValue<double>{Range<double>{-1e4, 1e4, false, false, "m"}},
    "[x_min, y_min, x_max, y_max]: where the movers start and draw their waypoints, in the env "
    "frame (e.g. a corridor people walk along); []: the world's region (world/region, else the "
    "arena or the map).");
  v("movers/social_strength", c.social_strength, atLeast(0.0, "m/s^2"),
    "A: the social force's acceleration at contact; it falls off as exp(-gap / social_range).");
  v("movers/social_range", c.social_range, positiveUpTo(100.0, "m"), "B: its fall-off length.");
  v("movers/relaxation_time", c.relaxation_time, positiveUpTo(100.0, "s"),
    "tau: a mover's velocity relaxes to its desired velocity with this time constant.");
}

}  // namespace jetbot_rl
