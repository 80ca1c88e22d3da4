#include "sensors/camera_sensor.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "env/env_physics.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "robot/bullet_conversions.h"

namespace jetbot_rl {
namespace {

// Camera noise of env e: the stream of env id e + kCameraStream (another than its other streams),
// of the robot's camera k > 0: e + kCameraStream + k x kCameraStride; its appearance draws (the
// same for all its cameras: one look per episode): e + kAppearanceStream.
constexpr std::uint64_t kCameraStream = streams::kCamera;
constexpr std::uint64_t kCameraStride = 1ULL << 32;  // more than any env id
constexpr std::uint64_t kAppearanceStream = streams::kAppearance;

}  // namespace

CameraSensor::CameraSensor(const CameraSpec& spec, int index, const RobotModel& robot,
                           std::shared_ptr<CameraWorld> world, int num_envs, std::uint64_t seed,
                           BatchImages* out, bool keep_finals, bool robot_visuals)
    : spec_(spec),
      noise_stream_(kCameraStream + static_cast<std::uint64_t>(index) * kCameraStride),
      model_(spec.intrinsics),
      world_(std::move(world)),
      out_(out ? *out : own_),
      pixels_(static_cast<std::size_t>(spec.intrinsics.width) * spec.intrinsics.height),
      poses_(num_envs, Eigen::Isometry3d::Identity()),
      age_(num_envs, 0),
      jitter_(num_envs, Eigen::Isometry3d::Identity()),
      robots_(num_envs) {
  if (robot_visuals) {
    try {
      robot_ = world_->addRobot(robot, spec.link);
    } catch (const ModelError& e) {
      throw ModelError(std::string(e.what()) +
                       " (the camera draws the robots by their visuals; camera/robot_visuals: "
                       "false draws none)");
    }
  }
  out_.width = spec.intrinsics.width;
  out_.height = spec.intrinsics.height;
  const auto n = static_cast<std::size_t>(num_envs);
  out_.rgb.assign(spec.rgb ? n * pixels_ * 3 : 0, 0);
  out_.depth.assign(spec.depth ? n * pixels_ : 0, 0.0f);
  out_.label.assign(spec.label ? n * pixels_ : 0, 0);
  out_.fresh.assign(n, 0);
  if (keep_finals) {
    finals_.rgb.assign(out_.rgb.size(), 0);
    finals_.depth.assign(out_.depth.size(), 0.0f);
    finals_.label.assign(out_.label.size(), 0);
  }
  for (int e = 0; e < num_envs; ++e) {
    scenes_.push_back(std::make_unique<CameraEnvScene>(*world_, robot_));
    scenes_.back()->setShadows(spec.shadows);
    noise_.emplace_back(seed, e + noise_stream_);
    appearance_rng_.emplace_back(seed, e + kAppearanceStream);
  }
}

void CameraSensor::reseed(int env, std::uint64_t seed) {
  noise_[env] = Rng(seed, env + noise_stream_);
  appearance_rng_[env] = Rng(seed, env + kAppearanceStream);
}

void CameraSensor::forgetNewReadings() { std::fill(out_.fresh.begin(), out_.fresh.end(), 0); }

namespace {

/// Copies image `from` of `count` values each of `src` to image `to` of `dst`.
template <typename T>
void copyImage(const std::vector<T>& src, std::size_t from, std::vector<T>& dst, std::size_t to,
               std::size_t count) {
  if (src.empty()) return;
  std::copy_n(src.begin() + static_cast<std::ptrdiff_t>(from * count), count,
              dst.begin() + static_cast<std::ptrdiff_t>(to * count));
}

/// Appends image `from` of `count` values each of `src` to `dst`.
template <typename T>
void appendImage(const std::vector<T>& src, std::size_t from, std::vector<T>& dst,
                 std::size_t count) {
  if (src.empty()) return;
  const auto first = src.begin() + static_cast<std::ptrdiff_t>(from * count);
  dst.insert(dst.end(), first, first + static_cast<std::ptrdiff_t>(count));
}

}  // namespace

void CameraSensor::keepFinal(int env) {
  if (finals_.rgb.size() != out_.rgb.size() || finals_.depth.size() != out_.depth.size() ||
      finals_.label.size() != out_.label.size()) {
    throw Error("CameraSensor::keepFinal: the sensor was made without keep_finals");
  }
  const auto e = static_cast<std::size_t>(env);
  copyImage(out_.rgb, e, finals_.rgb, e, pixels_ * 3);
  copyImage(out_.depth, e, finals_.depth, e, pixels_);
  copyImage(out_.label, e, finals_.label, e, pixels_);
}

void CameraSensor::appendFinal(int env, BatchImages& out) const {
  const auto e = static_cast<std::size_t>(env);
  out.width = out_.width;
  out.height = out_.height;
  appendImage(finals_.rgb, e, out.rgb, pixels_ * 3);
  appendImage(finals_.depth, e, out.depth, pixels_);
  appendImage(finals_.label, e, out.label, pixels_);
}

void CameraSensor::afterStep(int env, const SensedEnv& sensed) {
  out_.fresh[env] = 0;
  if (++age_[env] >= static_cast<std::uint32_t>(spec_.update_every)) render(env, sensed);
}

void CameraSensor::afterReset(int env, const SensedEnv& sensed) {
  scenes_[env]->setObstacles(sensed.layout.obstacles);
  scenes_[env]->setFloor(sensed.layout.floor);
  if (spec_.randomizesAppearance()) drawAppearance(env);
  render(env, sensed);
}

void CameraSensor::drawAppearance(int env) {
  Rng& rng = appearance_rng_[env];
  Appearance a;
  if (spec_.random_colours) {
    a.material_colours = false;
    for (Eigen::Vector3f* c : {&a.ground, &a.wall, &a.map, &a.obstacle, &a.mover}) {
      *c = uniformColour(rng, 0.1, 0.9);
    }
    a.floor_tint = uniformColour(rng, 0.7, 1.3);
  }
  if (!spec_.light_intensity.empty()) {
    a.light = static_cast<float>(uniform(rng, spec_.light_intensity[0], spec_.light_intensity[1]));
  }
  if (spec_.random_light_direction) {
    const double azimuth = uniform(rng, -kPi, kPi), elevation = uniform(rng, 0.35, 1.4);
    a.light_direction =
        -Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                         std::cos(elevation) * std::sin(azimuth), std::sin(elevation))
             .cast<float>();
  }
  if (!spec_.exposure.empty()) {
    a.exposure = static_cast<float>(uniform(rng, spec_.exposure[0], spec_.exposure[1]));
  }
  scenes_[env]->setAppearance(a);
  if (!spec_.pose_jitter.empty()) {
    const double p = spec_.pose_jitter[0], q = spec_.pose_jitter[1];
    Eigen::Isometry3d jitter = Eigen::Isometry3d::Identity();
    jitter.translation() =
        Eigen::Vector3d(uniform(rng, -p, p), uniform(rng, -p, p), uniform(rng, -p, p));
    const double roll = uniform(rng, -q, q), pitch = uniform(rng, -q, q), yaw = uniform(rng, -q, q);
    jitter.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
    jitter_[env] = jitter;
  }
}

void CameraSensor::render(int env, const SensedEnv& sensed) {
  CameraEnvScene& scene = *scenes_[env];
  poses_[env] = opticalFrame(toEigen(sensed.physics.linkPose(spec_.body)) * spec_.pose_in_body *
                             jitter_[env]);
  // Movers no ray can meet are left out of the scene (a shadow ray could meet them: not then).
  const ViewCone cone_of_view(model_, poses_[env]);
  const ViewCone* cone = spec_.shadows ? nullptr : &cone_of_view;
  if (robot_) {
    if (sensed.people) scene.setMovers(*sensed.people, cone);
    scene.setRobots(robotPoses(env, sensed), /*commit=*/true, cone);
  } else if (sensed.movers) {  // people and the other robots as cylinders
    scene.setMovers(*sensed.movers, cone);
  }
  const auto e = static_cast<std::size_t>(env);
  CameraImageView view;
  if (spec_.rgb) view.rgb = &out_.rgb[e * pixels_ * 3];
  if (spec_.depth) view.depth = &out_.depth[e * pixels_];
  if (spec_.label) view.label = &out_.label[e * pixels_];
  scene.render(model_, poses_[env], view);
  if (view.rgb && (spec_.noise_std > 0.0 || spec_.noise_mean != 0.0)) addNoise(env, view.rgb);
  age_[env] = 0;
  out_.fresh[env] = 1;
}

const std::vector<RobotPose>& CameraSensor::robotPoses(int env, const SensedEnv& sensed) {
  std::vector<RobotPose>& robots = robots_[env];
  const WorldRobots& world = sensed.robots;
  std::size_t count = 1;
  for (int row = world.first; row < world.first + world.count; ++row) {
    count += row != env && (*world.present)[static_cast<std::size_t>(row)] ? 1 : 0;
  }
  robots.resize(count);
  const auto place = [](RobotPose& pose, const EnvPhysics& physics, bool own) {
    pose.own = own;
    pose.bodies.resize(static_cast<std::size_t>(physics.numBodies()));
    for (int b = 0; b < physics.numBodies(); ++b) pose.bodies[b] = toEigen(physics.linkPose(b));
  };
  place(robots[0], sensed.physics, true);
  std::size_t next = 1;
  for (int row = world.first; row < world.first + world.count; ++row) {
    if (row == env || !(*world.present)[static_cast<std::size_t>(row)]) continue;
    place(robots[next++], *(*world.physics)[static_cast<std::size_t>(row)], false);
  }
  return robots;
}

void CameraSensor::addNoise(int env, std::uint8_t* rgb) {
  Rng& rng = noise_[env];
  for (std::size_t i = 0; i < pixels_ * 3; ++i) {
    const double value = rgb[i] / 255.0 + spec_.noise_mean + spec_.noise_std * rng.gaussian();
    rgb[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(value, 0.0, 1.0)));
  }
}

}  // namespace jetbot_rl
