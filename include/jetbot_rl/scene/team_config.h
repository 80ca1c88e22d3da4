#pragma once

// Several robots in one world (docs/team.md): robots_per_env
// robots share each env's world, each one row of the batch. One robot per env by default.

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// The parameters of several robots per env.
struct TeamConfig {
  int robots_per_env = 1;    ///< K: robots in each env's world, each a row of the batch.
  double swap_radius = 0.0;  ///< > 0: circle swap, the K robots on a circle of this radius [m].
  bool rounds = false;       ///< The K robots start together; one that ended waits for the rest.
};

template <typename C, typename V>
IfConfig<C, TeamConfig> visitFields(C& c, V&& v) {
  v("robots_per_env", c.robots_per_env, inRange(1, 1000),
    "K robots in each env's world (num_envs worlds): the batch has num_envs x K rows, robot k "
    "of env e at row e x K + k, each an agent with its own actions, observation, reward and "
    "episode. They see each other in their scans and collide (outcome 4); movers (movers/...) "
    "walk in the world among all K, and random obstacles (world/num_boxes, num_cylinders) and "
    "generated layouts (world/families) are the world's, drawn when all K start anew (in a "
    "layout each robot starts on its free floor with a path to its goal). K > 1 needs "
    "world/random_start or swap_radius.");
  v("swap_radius", c.swap_radius, Range<double>{0.0, 1000.0, false, false, "m", "0: off"},
    "Circle swap: the K robots of an env start evenly spaced on a circle of this radius about "
    "world/spawn, facing the centre (plus initial_yaw), each with its goal at the opposite "
    "point. A robot whose episode ended starts again at its own point, or, while another robot "
    "is within world/start_clearance of it, at a free point of the circle drawn from its stream. "
    "0: off.");
  v("rounds", c.rounds, AnyValue{},
    "Rounds (K > 1): the K robots of an env start together and each runs one episode; a robot "
    "whose episode ended waits where it stopped, out of the others' way (they no longer see or "
    "touch it), its row observing what it saw last, with reward 0 and no end. When every robot "
    "of the env has ended, each waiting row ends a stand-in episode with outcome 5 (waited: "
    "counted by no rate) and all start the next round (a circle swap: each at its own point). "
    "The literature's circle swap, where the middle empties as robots arrive; false: a robot "
    "starts again as soon as its episode ends.");
}

}  // namespace jetbot_rl
