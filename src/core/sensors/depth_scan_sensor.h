#pragma once

#include "jetbot_rl/sensors/depth_scan.h"
#include "sensors/camera_sensor.h"
#include "sensors/scan_sensor.h"

namespace jetbot_rl {

/// The scan of every env taken from its camera's depth image (scan/source camera_depth;
/// depthToScan()) whenever the camera made one: the sensor comes after the camera in the step.
class DepthScanSensor : public ScanSensor {
 public:
  /// `camera`: the batch camera, which must outlive the sensor and make depth images.
  DepthScanSensor(const ScannerSpec& spec, const CameraSensor& camera, int num_envs,
                  std::uint64_t seed);

  void afterStep(int env, const SensedEnv& sensed) override;

 protected:
  void scan(int env, const SensedEnv& sensed) override;

 private:
  const CameraSensor& camera_;
};

}  // namespace jetbot_rl
