#include "sensors/camera_sensor.h"

#include <algorithm>
#include <cmath>

#include "env/env_physics.h"
#include "robot/bullet_conversions.h"

namespace jetbot_rl {
namespace {

// Camera noise of env e: the stream of env id e + kCameraStream (another than its other streams).
constexpr std::uint64_t kCameraStream = 1ULL << 42;

}  // namespace

CameraSensor::CameraSensor(const CameraSpec& spec, const WorldModel* world, int num_envs,
                           std::uint64_t seed, BatchImages& out)
    : spec_(spec),
      model_(spec.intrinsics),
      world_(world),
      out_(out),
      pixels_(static_cast<std::size_t>(spec.intrinsics.width) * spec.intrinsics.height),
      poses_(num_envs, Eigen::Isometry3d::Identity()),
      age_(num_envs, 0) {
  out_.width = spec.intrinsics.width;
  out_.height = spec.intrinsics.height;
  const auto n = static_cast<std::size_t>(num_envs);
  out_.rgb.assign(spec.rgb ? n * pixels_ * 3 : 0, 0);
  out_.depth.assign(spec.depth ? n * pixels_ : 0, 0.0f);
  out_.label.assign(spec.label ? n * pixels_ : 0, 0);
  out_.fresh.assign(n, 0);
  for (int e = 0; e < num_envs; ++e) {
    scenes_.push_back(std::make_unique<CameraEnvScene>(world_));
    noise_.emplace_back(seed, e + kCameraStream);
  }
}

void CameraSensor::reseed(int env, std::uint64_t seed) {
  noise_[env] = Rng(seed, env + kCameraStream);
}

void CameraSensor::forgetNewReadings() { std::fill(out_.fresh.begin(), out_.fresh.end(), 0); }

void CameraSensor::afterStep(int env, const SensedEnv& sensed) {
  out_.fresh[env] = 0;
  if (++age_[env] >= static_cast<std::uint32_t>(spec_.update_every)) render(env, sensed);
}

void CameraSensor::afterReset(int env, const SensedEnv& sensed) {
  scenes_[env]->setObstacles(sensed.layout.obstacles);
  render(env, sensed);
}

void CameraSensor::render(int env, const SensedEnv& sensed) {
  CameraEnvScene& scene = *scenes_[env];
  if (sensed.movers) scene.setMovers(*sensed.movers);
  poses_[env] = opticalFrame(toEigen(sensed.physics.linkPose(spec_.body)) * spec_.pose_in_body);
  const auto e = static_cast<std::size_t>(env);
  CameraImageView view;
  if (spec_.rgb) view.rgb = &out_.rgb[e * pixels_ * 3];
  if (spec_.depth) view.depth = &out_.depth[e * pixels_];
  if (spec_.label) view.label = &out_.label[e * pixels_];
  scene.render(model_, poses_[env], view);
  if (view.rgb && spec_.noise_std > 0.0) addNoise(env, view.rgb);
  age_[env] = 0;
  out_.fresh[env] = 1;
}

void CameraSensor::addNoise(int env, std::uint8_t* rgb) {
  Rng& rng = noise_[env];
  for (std::size_t i = 0; i < pixels_ * 3; ++i) {
    const double value = rgb[i] / 255.0 + spec_.noise_mean + spec_.noise_std * rng.gaussian();
    rgb[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(value, 0.0, 1.0)));
  }
}

}  // namespace jetbot_rl
