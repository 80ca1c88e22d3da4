#pragma once

// The `barn` family of generated worlds: a field of posts grown by a cellular automaton, as the
// BARN benchmark draws its worlds for a Jackal, scaled to the robot (docs/world.md).

#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/world/world_generation.h"

namespace jetbot_rl {

/// Adds `o` unless `out` already holds `max` obstacles; counts what is left out (every family's
/// obstacle slots).
inline void addObstacle(const Obstacle& o, int max, std::vector<Obstacle>& out, int& left_out) {
  if (static_cast<int>(out.size()) < max) {
    out.push_back(o);
  } else {
    ++left_out;
  }
}

/// Appends the posts of a BARN field over `a.area` at difficulty `d` in [0, 1], drawn from `rng`;
/// at most `max` obstacles in `out` (the rest counted in `left_out`).
void barnField(double d, const GenerationArea& a, Rng& rng, int max, std::vector<Obstacle>& out,
               int& left_out);

}  // namespace jetbot_rl
