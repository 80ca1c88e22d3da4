#pragma once
// A robot as cameras see it: per body, one Embree scene of its URDF visuals (boxes, cylinders,
// spheres and meshes as triangles) in the body's link frame, with each geometry's material; every
// env scene instances the bodies of its robots at their poses (the model/data split again).
#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/sensors/surface_material.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace jetbot_rl {

/// Textures read so far, one image per file, and their decoded bytes.
struct TextureCache {
  std::map<std::string, std::shared_ptr<const TextureImage>> images;
  std::size_t bytes = 0;
};

/// The surfaces of visual `v` in its body's link frame [m], each with its material: one, in its
/// colour, or, for a mesh without a URDF colour, one per material of its file (its diffuse
/// colour or texture, as RViz draws it). ModelError naming the link for a mesh that cannot be
/// resolved or read, or a texture that cannot be read.
std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> visualSurfaces(
    const VisualGeometry& v, TextureCache& textures);

class CameraRobot {
 public:
  /// The visuals of every body of `robot` on `device`; `hidden_link`'s (the camera's own link,
  /// its housing, which its rays start inside) are left out of the robot's own view. ModelError
  /// naming the link for a visual mesh that cannot be read.
  CameraRobot(RTCDeviceTy* device, const RobotModel& robot, const std::string& hidden_link);
  ~CameraRobot();
  CameraRobot(const CameraRobot&) = delete;
  CameraRobot& operator=(const CameraRobot&) = delete;

  int numBodies() const { return static_cast<int>(bodies_.size()); }
  /// Body `b` as the robot's own camera (`own`) or another robot's sees it; nullptr: nothing.
  RTCSceneTy* body(int b, bool own) const { return own ? bodies_[b].own : bodies_[b].all; }
  /// A sphere holding all of that scene: its centre in the body's link frame [m] and radius [m].
  const Eigen::Vector4d& boundingSphere(int b, bool own) const {
    return own ? bodies_[b].own_sphere : bodies_[b].sphere;
  }
  /// The colour of geometry `geometry` of that scene at its triangle `triangle`, where Embree's
  /// barycentric coordinates are `u`, `v`.
  Eigen::Vector3f colour(int b, bool own, unsigned geometry, unsigned triangle, float u,
                         float v) const {
    return (own ? bodies_[b].own_materials : bodies_[b].materials).at(geometry).at(triangle, u, v);
  }

 private:
  struct Body {
    RTCSceneTy* all = nullptr;
    RTCSceneTy* own = nullptr;  // == all when the hidden link is not among its visuals
    std::vector<SurfaceMaterial> materials, own_materials;  // per geometry id
    Eigen::Vector4d sphere = Eigen::Vector4d::Zero(), own_sphere = Eigen::Vector4d::Zero();
  };
  void release();

  std::vector<Body> bodies_;
};

}  // namespace jetbot_rl
