#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace jetbot_rl {

/// The offsets of an env's random streams besides its own (env id e: its layouts, starts and
/// randomisation): stream e + offset for each other purpose, one offset per purpose, so that no
/// two purposes draw the same numbers (all here, where a new one can be checked against the rest).
namespace streams {
inline constexpr std::uint64_t kNoise = 1ULL << 40;       ///< Observation and action noise.
inline constexpr std::uint64_t kScan = 1ULL << 41;        ///< The laser scanner's noise.
inline constexpr std::uint64_t kMovers = 1ULL << 42;      ///< The people's walks.
inline constexpr std::uint64_t kCamera = 1ULL << 43;      ///< The camera's noise.
inline constexpr std::uint64_t kAppearance = 1ULL << 44;  ///< The camera's appearance draws.
}  // namespace streams

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

/// A colour (RGB) whose channels are each uniform in [lo, hi], drawn red first.
inline Eigen::Vector3f uniformColour(Rng& rng, double lo, double hi) {
  Eigen::Vector3f c;
  for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(uniform(rng, lo, hi));
  return c;
}

}  // namespace jetbot_rl
