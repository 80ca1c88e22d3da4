#pragma once

#include <cstdint>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "sensors/env_sensor.h"

namespace jetbot_rl {

class WorldModel;

/// The planar laser scanner of every env (docs/world.md): each env's latest scan, its age in
/// control steps, whether it is new, and its own noise stream.
class ScanSensor : public EnvSensor {
 public:
  /// `world` (or none) is what the beams hit besides each env's obstacles.
  ScanSensor(const ScannerSpec& spec, const WorldModel* world, int num_envs, std::uint64_t seed);

  void reseed(int env, std::uint64_t seed) override;
  void forgetNewReadings() override;
  void afterStep(int env, const SensedEnv& sensed) override;
  void afterReset(int env, const SensedEnv& sensed) override;

  const ScannerSpec& spec() const { return spec_; }
  /// Env `env`'s latest scan: spec().samples ranges [m] (REP 117 values).
  const float* ranges(int env) const {
    return &ranges_[static_cast<std::size_t>(env) * spec_.samples];
  }
  /// True when env `env` took a new scan in the last step or reset.
  bool isNew(int env) const { return new_[env] != 0; }

 protected:
  /// Takes env `env`'s scan now: its rays cast in its world.
  virtual void scan(int env, const SensedEnv& sensed);

  ScannerSpec spec_;
  const WorldModel* world_;
  std::vector<float> ranges_;       // per env: samples ranges
  std::vector<std::uint32_t> age_;  // per env: control steps since its last scan
  std::vector<std::uint8_t> new_;   // per env: a new scan in the last step or reset
  std::vector<Rng> noise_;          // per env
};

}  // namespace jetbot_rl
