#pragma once

#include <cmath>
#include <cstdint>

namespace jetbot_rl {

/// Small counter-based random stream (SplitMix64): one per env, reproducible on every platform.
class Rng {
 public:
  /// The stream of env `env_id` under `seed`; independent of every other env's.
  Rng(std::uint64_t seed = 0, std::uint64_t env_id = 0)
      : state_(mix(seed ^ mix(env_id + 0x632be59bd9b4e019ULL))) {}
  /// Next 64 random bits.
  std::uint64_t next() { return mix(state_ += 0x9e3779b97f4a7c15ULL); }
  /// Uniform double in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Standard normal value (Box-Muller on two uniform() draws; the second value is not kept).
  double gaussian() {
    const double u1 = 1.0 - uniform();  // (0, 1]: log() stays finite
    const double u2 = uniform();
    constexpr double kTwoPi = 6.283185307179586;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
  }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

/// Uniform double in [lo, hi) from `rng` (one draw).
inline double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

}  // namespace jetbot_rl
