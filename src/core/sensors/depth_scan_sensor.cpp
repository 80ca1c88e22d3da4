#include "sensors/depth_scan_sensor.h"

#include "env/env_physics.h"
#include "robot/bullet_conversions.h"

namespace jetbot_rl {

DepthScanSensor::DepthScanSensor(const ScannerSpec& spec, const CameraSensor& camera, int num_envs,
                                 std::uint64_t seed)
    : ScanSensor(spec, nullptr, num_envs, seed), camera_(camera) {}

void DepthScanSensor::afterStep(int env, const SensedEnv& sensed) {
  new_[env] = 0;
  if (camera_.isNew(env)) scan(env, sensed);
}

void DepthScanSensor::scan(int env, const SensedEnv& sensed) {
  const std::size_t pixels =
      static_cast<std::size_t>(camera_.model().width()) * camera_.model().height();
  depthToScan(spec_, camera_.model(),
              &camera_.images().depth[static_cast<std::size_t>(env) * pixels],
              camera_.opticalPose(env), toEigen(sensed.physics.linkPose(0)),
              &ranges_[static_cast<std::size_t>(env) * spec_.samples]);
  age_[env] = 0;
  new_[env] = 1;
}

}  // namespace jetbot_rl
