#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/rng.h"
#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "sensors/env_sensor.h"

namespace jetbot_rl {

class RobotModel;
class WorldModel;

/// The camera of every env (docs/camera.md): one Embree scene of the shared world, one scene per
/// env with its obstacles and movers, each env's latest images written into the batch's
/// BatchImages, their cadence, and a noise stream per env.
class CameraSensor : public EnvSensor {
 public:
  /// `world` (the world's scene, shared by the robot's cameras) is what the camera sees besides
  /// each env's bodies and its robots (`robot`'s URDF visuals; ModelError for a visual mesh that
  /// cannot be read); images go to `out` (sized here), which must outlive the sensor, or (nullptr)
  /// into the sensor's own. `index`: the robot's camera index (its noise stream; 0 draws what a
  /// robot with one camera draws). `keep_finals`: keepFinal() is used (memory for a second image
  /// of every env); `robot_visuals`: the robots are drawn by `robot`'s visuals (else the others as
  /// cylinders).
  CameraSensor(const CameraSpec& spec, int index, const RobotModel& robot,
               std::shared_ptr<CameraWorld> world, int num_envs, std::uint64_t seed,
               BatchImages* out, bool keep_finals, bool robot_visuals);

  void reseed(int env, std::uint64_t seed) override;
  void forgetNewReadings() override;
  void afterStep(int env, const SensedEnv& sensed) override;
  void afterReset(int env, const SensedEnv& sensed) override;

  const CameraSpec& spec() const { return spec_; }
  const CameraModel& model() const { return model_; }
  /// Every env's latest images.
  const BatchImages& images() const { return out_; }
  /// Keeps env `env`'s current images as its ended episode's last (its reset renders anew).
  void keepFinal(int env);
  /// Appends env `env`'s kept images to `out` (whose width and height it sets).
  void appendFinal(int env, BatchImages& out) const;
  /// True when env `env`'s images were made in the last step or reset.
  bool isNew(int env) const { return out_.fresh[env] != 0; }
  /// Env `env`'s camera optical frame in its env frame when the images were made.
  const Eigen::Isometry3d& opticalPose(int env) const { return poses_[env]; }
  /// How env `env`'s scene looks in its current episode.
  const Appearance& appearance(int env) const { return scenes_[env]->appearance(); }

 private:
  void render(int env, const SensedEnv& sensed);
  /// Env `env`'s robots where they stand: its own first, then the others present in its world.
  const std::vector<RobotPose>& robotPoses(int env, const SensedEnv& sensed);
  /// Gazebo's camera noise on env `env`'s rgb image: N(mean, std) per channel on [0, 1].
  void addNoise(int env, std::uint8_t* rgb);
  /// Appearance randomisation: env `env`'s look and camera pose jitter for its new episode.
  void drawAppearance(int env);

  CameraSpec spec_;
  std::uint64_t noise_stream_;  // env e's noise: stream e + noise_stream_
  CameraModel model_;
  std::shared_ptr<CameraWorld> world_;
  const CameraRobot* robot_ = nullptr;  // the robots as this camera draws them (world_'s)
  std::vector<std::unique_ptr<CameraEnvScene>> scenes_;  // per env
  BatchImages own_;                                      // the images when none are given
  BatchImages& out_;
  BatchImages finals_;  // per env: its ended episode's last images (keepFinal())
  std::size_t pixels_;
  std::vector<Eigen::Isometry3d> poses_;        // per env
  std::vector<std::uint32_t> age_;              // per env: control steps since its last images
  std::vector<Rng> noise_;                      // per env
  std::vector<Rng> appearance_rng_;             // per env
  std::vector<Eigen::Isometry3d> jitter_;       // per env: the camera's offset in its body frame
  std::vector<std::vector<RobotPose>> robots_;  // per env: its world's robots at its last image
};

}  // namespace jetbot_rl
