#pragma once

// Several robots in one world (docs/team.md): robots_per_env
// robots share each env's world, each one row of the batch. One robot per env by default.

#include "jetbot_rl/config_fields.h"

namespace jetbot_rl {

/// The parameters of several robots per env.
struct TeamConfig {
  int robots_per_env = 1;    ///< K: robots in each env's world, each a row of the batch.
  double swap_radius = 0.0;  ///< > 0: circle swap, the K robots on a circle of this radius [m].
};

template <typename C, typename V>
IfConfig<C, TeamConfig> visitFields(C& c, V&& v) {
  v("robots_per_env", c.robots_per_env, inRange(1, 1000),
    "K robots in each env's world (num_envs worlds): the batch has num_envs x K rows, robot k "
    "of env e at row e x K + k, each an agent with its own actions, observation, reward and "
    "episode. They see each other in their scans and collide (outcome 4). K > 1 needs a world "
    "without random or generated obstacles and without movers, and world/random_start or "
    "swap_radius.");
  v("swap_radius", c.swap_radius, Range<double>{0.0, 1000.0, false, false, "m", "0: off"},
    "Circle swap: the K robots of an env start evenly spaced on a circle of this radius about "
    "world/spawn, facing the centre (plus initial_yaw), each with its goal at the opposite "
    "point. A robot whose episode ended starts again at its own point, or, while another robot "
    "is within world/start_clearance of it, at a free point of the circle drawn from its stream. "
    "0: off.");
}

}  // namespace jetbot_rl
