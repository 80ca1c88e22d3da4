#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace jetbot_rl {

class EnvPhysics;
struct EnvLayout;
struct Obstacle;

/// The robots of one world: rows [first, first + count) of `physics`, those with `present[row]`
/// in the world now.
struct WorldRobots {
  const std::vector<std::unique_ptr<EnvPhysics>>* physics = nullptr;
  const std::vector<std::uint8_t>* present = nullptr;
  int first = 0, count = 0;
};

/// What a sensor reads an env from: its physics, its layout of the current episode, its movers
/// where they stand (or none: people and the other robots, as cylinders), the people alone, and
/// the robots of its world (count 0: it alone).
struct SensedEnv {
  const EnvPhysics& physics;
  const EnvLayout& layout;
  const std::vector<Obstacle>* movers = nullptr;
  const std::vector<Obstacle>* people = nullptr;
  WorldRobots robots;
};

/**
 * A sensor every env of a batch carries (BatchedEnv steps it; a second sensor is a new
 * implementation): it owns its readings, its cadence and its noise streams, one per env, and is
 * called concurrently for different envs from the stepping threads.
 */
class EnvSensor {
 public:
  virtual ~EnvSensor() = default;
  /// Restarts env `env`'s noise stream from `seed` (a reset with a seed).
  virtual void reseed(int env, std::uint64_t seed) = 0;
  /// Before the envs of a reset() are reset: no env has a new reading any more.
  virtual void forgetNewReadings() = 0;
  /// After a control step of env `env`'s physics: reads when its cadence is due.
  virtual void afterStep(int env, const SensedEnv& sensed) = 0;
  /// After env `env` was reset: reads.
  virtual void afterReset(int env, const SensedEnv& sensed) = 0;
};

}  // namespace jetbot_rl
