#include "sensors/scan_sensor.h"

#include <algorithm>

#include "env/env_physics.h"
#include "robot/bullet_conversions.h"

namespace jetbot_rl {
namespace {

// Scan noise of env e: the stream of env id e + kScanStream (another than its noise stream's).
constexpr std::uint64_t kScanStream = streams::kScan;

}  // namespace

ScanSensor::ScanSensor(const ScannerSpec& spec, const WorldModel* world, int num_envs,
                       std::uint64_t seed)
    : spec_(spec),
      world_(world),
      ranges_(static_cast<std::size_t>(num_envs) * spec.samples, kNoReturn),
      age_(num_envs, 0),
      new_(num_envs, 0) {
  for (int e = 0; e < num_envs; ++e) noise_.emplace_back(seed, e + kScanStream);
}

void ScanSensor::reseed(int env, std::uint64_t seed) { noise_[env] = Rng(seed, env + kScanStream); }

void ScanSensor::forgetNewReadings() { std::fill(new_.begin(), new_.end(), 0); }

void ScanSensor::afterStep(int env, const SensedEnv& sensed) {
  new_[env] = 0;
  if (++age_[env] >= static_cast<std::uint32_t>(spec_.update_every)) scan(env, sensed);
}

void ScanSensor::afterReset(int env, const SensedEnv& sensed) { scan(env, sensed); }

void ScanSensor::scan(int env, const SensedEnv& sensed) {
  const Eigen::Isometry3d sensor =
      toEigen(sensed.physics.linkPose(spec_.body)) * spec_.pose_in_body;
  castScan(spec_, world_, sensed.layout.obstacles, sensor, noise_[env],
           &ranges_[static_cast<std::size_t>(env) * spec_.samples], sensed.movers);
  age_[env] = 0;
  new_[env] = 1;
}

}  // namespace jetbot_rl
