#include "jetbot_rl/dataset/notebook_dataset.h"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/tasks/road_following_task.h"

namespace jetbot_rl {
namespace {

/// What blocks the way: anything but the ground, the sky and the robots.
bool obstructs(std::uint8_t label) {
  const auto c = static_cast<SurfaceClass>(label);
  return c == SurfaceClass::kWall || c == SurfaceClass::kMap || c == SurfaceClass::kObstacle ||
         c == SurfaceClass::kMover;
}

Eigen::Isometry3d rootPose(const BatchedEnv& env, int row) {
  const RootState s = env.view(row).rootState();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = s.orientation.toRotationMatrix();
  pose.translation() = s.position;
  return pose;
}

void writeJpeg(const std::string& path, const EnvImages& images, int quality) {
  if (!stbi_write_jpg(path.c_str(), images.width, images.height, 3, images.rgb, quality)) {
    throw Error("cannot write " + path);
  }
}

}  // namespace

bool blockedAhead(const BatchedEnv& env, const CameraModel& camera, int row, double distance,
                  double half_width) {
  const EnvImages images = env.view(row).images();
  if (!images.depth || !images.label) {
    throw InputError(
        "the blocked test reads the camera's depth and label images: give "
        "camera/images [rgb, depth, label]");
  }
  const Eigen::Isometry3d to_base = rootPose(env, row).inverse() * env.view(row).cameraPose();
  const std::vector<Eigen::Vector3f>& rays = camera.pixelRays();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const float depth = images.depth[i];
    if (!obstructs(images.label[i]) || !std::isfinite(depth)) continue;
    const Eigen::Vector3d p = to_base * (static_cast<double>(depth) * rays[i].cast<double>());
    if (p.x() > 0.0 && p.x() <= distance && std::abs(p.y()) <= half_width) return true;
  }
  return false;
}

std::optional<Eigen::Vector2d> roadTarget(const BatchedEnv& env, const CameraModel& camera, int row,
                                          double lookahead) {
  const auto* road = dynamic_cast<const RoadFollowingTask*>(&env.task());
  if (!road) throw InputError("the road following target needs task road_following");
  const Track& track = road->track(row);
  const Eigen::Vector2d p = track.at(road->place(row).s + lookahead);
  const std::optional<Eigen::Vector2d> pixel =
      camera.project(env.view(row).cameraPose().inverse() * Eigen::Vector3d(p.x(), p.y(), 0.0));
  if (!pixel || pixel->x() < 0.0 || pixel->y() < 0.0 || pixel->x() >= camera.width() ||
      pixel->y() >= camera.height()) {
    return std::nullopt;
  }
  return pixel;
}

DatasetSummary writeNotebookDataset(BatchedEnv& env, const DatasetOptions& o) {
  namespace fs = std::filesystem;
  const CameraSpec* camera = env.camera();
  if (!camera || !camera->rgb) {
    throw ConfigError(
        "the robot has no camera making rgb images (a Gazebo "
        "camera block, e.g. urdf/jetbot_camera.urdf)");
  }
  const bool collision = o.kind == DatasetKind::kCollisionAvoidance;
  if (collision && (!camera->depth || !camera->label)) {
    throw ConfigError(
        "collision_avoidance needs camera/images [rgb, depth, "
        "label] (the blocked test reads depth and label)");
  }
  if (!collision && !dynamic_cast<const RoadFollowingTask*>(&env.task())) {
    throw ConfigError("road_following needs task road_following");
  }
  const fs::path out(o.out);
  const fs::path blocked_dir = out / "blocked", free_dir = out / "free";
  std::error_code made;
  for (const fs::path& dir :
       collision ? std::vector<fs::path>{blocked_dir, free_dir} : std::vector<fs::path>{out}) {
    fs::create_directories(dir, made);
    if (made) throw Error("cannot make the folder " + dir.string() + ": " + made.message());
  }
  const double half_width = env.spec().observer.footprint_radius;
  const CameraModel model(camera->intrinsics);  // its pixel rays: once, not per image
  const int half = o.count / 2;
  DatasetSummary summary;
  const long long max_resets = 1000LL * std::max(1, o.count);
  char name[64];
  while (collision ? summary.blocked < half || summary.free < o.count - half
                   : summary.road < o.count) {
    if (summary.resets >= max_resets) {
      throw Error(std::to_string(summary.resets) + " resets gave " +
                  std::to_string(summary.blocked) + " blocked and " + std::to_string(summary.free) +
                  " free images of " + std::to_string(o.count) +
                  ": make obstacles denser or sparser (world/...) or change --blocked-distance");
    }
    env.reset({}, o.seed + static_cast<std::uint64_t>(summary.resets++));
    for (int row = 0; row < env.numEnvs(); ++row) {
      const EnvImages images = env.view(row).images();
      if (collision) {
        const bool blocked = blockedAhead(env, model, row, o.blocked_distance, half_width);
        int& n = blocked ? summary.blocked : summary.free;
        if (n >= (blocked ? half : o.count - half)) continue;
        std::snprintf(name, sizeof(name), "%06d.jpg", n++);
        writeJpeg(((blocked ? blocked_dir : free_dir) / name).string(), images, o.quality);
      } else if (summary.road < o.count) {
        const std::optional<Eigen::Vector2d> target = roadTarget(env, model, row, o.lookahead);
        if (!target) continue;
        std::snprintf(name, sizeof(name), "xy_%03d_%03d_%06d.jpg",
                      static_cast<int>(std::lround(target->x())),
                      static_cast<int>(std::lround(target->y())), summary.road++);
        writeJpeg((out / name).string(), images, o.quality);
      }
    }
  }
  return summary;
}

}  // namespace jetbot_rl
