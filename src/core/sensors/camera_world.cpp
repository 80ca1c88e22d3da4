// CameraWorld: the static bodies of a world as one Embree scene shared by every env's scene
// (camera_scene.h), with the robot's visuals.
#include <embree3/rtcore.h>

#include <algorithm>
#include <utility>

#include "jetbot_rl/sensors/camera_scene.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/world_model.h"
#include "sensors/camera_robot.h"
#include "sensors/embree_geometry.h"

namespace jetbot_rl {

CameraWorld::CameraWorld(const WorldModel* world, std::shared_ptr<const FloorImage> floor)
    : floor_(std::move(floor)) {
  // One build thread, the caller's: the same trees every run, no pool beside the env's threads.
  device_ = rtcNewDevice("threads=1,user_threads=0");
  if (!device_) throwEmbree(nullptr, "rtcNewDevice");
  scene_ = rtcNewScene(device_);
  if (!scene_) throwEmbree(device_, "rtcNewScene");
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);

  std::vector<Eigen::Vector3d> walls, blocks;
  // A Gazebo world read with its visuals is drawn by them; else by the shapes the scanner sees.
  const GazeboWorld* gazebo = world ? world->gazebo() : nullptr;
  const bool visuals = gazebo && !gazebo->visuals.empty();
  if (world) {
    for (const Obstacle& w : world->walls()) appendObstacleSurface(w, walls);
    for (const Obstacle& o : world->worldObstacles()) {
      if (!visuals) appendObstacleSurface(o, blocks);
    }
  }
  if (world && world->map() && !visuals) {
    for (const Eigen::AlignedBox2d& r : world->mapRectangles()) {
      Obstacle block;
      block.center = world->mapPose() * r.center();
      block.yaw = Eigen::Rotation2Dd(world->mapPose().linear()).angle();
      block.half_extents = 0.5 * r.sizes();
      block.height = world->config().obstacle_height;
      appendObstacleSurface(block, blocks);
    }
  }
  empty_ = rtcNewScene(device_);
  if (!empty_) throwEmbree(device_, "rtcNewScene");
  rtcCommitScene(empty_);
  if (!walls.empty()) {
    classes_.push_back(SurfaceClass::kWall);
    attachTriangles(device_, scene_, walls);
  }
  if (!blocks.empty()) {
    classes_.push_back(SurfaceClass::kMap);
    attachTriangles(device_, scene_, blocks);
  }
  if (visuals) {  // one geometry per colour, and one per texture
    std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> groups;
    for (const WorldVisual& v : gazebo->visuals) {
      auto at = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
        return v.texture ? g.first.texture == v.texture
                         : !g.first.texture && g.first.colour == v.colour;
      });
      if (at == groups.end()) at = groups.insert(groups.end(), {{v.colour, v.texture, {}}, {}});
      at->second.insert(at->second.end(), v.triangles.begin(), v.triangles.end());
      at->first.uv.insert(at->first.uv.end(), v.uv.begin(), v.uv.end());
    }
    for (auto& [material, corners] : groups) {
      const unsigned id = attachTriangles(device_, scene_, corners);
      if (classes_.size() <= id) classes_.resize(id + 1, SurfaceClass::kMap);
      if (materials_.size() <= id) materials_.resize(id + 1);
      classes_[id] = SurfaceClass::kMap;
      materials_[id] = std::move(material);
    }
  }
  rtcCommitScene(scene_);
}

const CameraRobot* CameraWorld::addRobot(const RobotModel& robot, const std::string& hidden_link) {
  std::unique_ptr<CameraRobot>& made = robots_[hidden_link];
  if (!made) made = std::make_unique<CameraRobot>(device_, robot, hidden_link);
  return made.get();
}

CameraWorld::~CameraWorld() {
  robots_.clear();  // their scenes belong to device_
  if (scene_) rtcReleaseScene(scene_);
  if (empty_) rtcReleaseScene(empty_);
  if (device_) rtcReleaseDevice(device_);
}

}  // namespace jetbot_rl
