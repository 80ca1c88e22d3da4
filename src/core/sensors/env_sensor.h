#pragma once

#include <cstdint>
#include <vector>

namespace jetbot_rl {

class EnvPhysics;
struct EnvLayout;
struct Obstacle;

/// What a sensor reads an env from: its physics, its layout of the current episode and its
/// movers where they stand (or none).
struct SensedEnv {
  const EnvPhysics& physics;
  const EnvLayout& layout;
  const std::vector<Obstacle>* movers = nullptr;
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
