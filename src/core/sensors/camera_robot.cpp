#include "sensors/camera_robot.h"

#include <embree3/rtcore.h>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/world/gazebo/mesh_loader.h"
#include "sensors/embree_geometry.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {
namespace {

/// A scene of `visuals` (each a geometry, its colour in `colours`), or nullptr for none;
/// `sphere`: (centre, radius) of a sphere holding them all.
RTCScene visualScene(RTCDevice device, const std::vector<const VisualGeometry*>& visuals,
                     std::vector<Eigen::Vector3f>& colours, Eigen::Vector4d& sphere) {
  if (visuals.empty()) return nullptr;
  Eigen::AlignedBox3d box;
  RTCScene scene = rtcNewScene(device);
  if (!scene) throwEmbree(device, "rtcNewScene");
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  try {
    for (const VisualGeometry* v : visuals) {
      const std::vector<Eigen::Vector3d> corners = visualTriangles(*v);
      if (corners.empty()) continue;
      for (const Eigen::Vector3d& c : corners) box.extend(c);
      const unsigned id = attachTriangles(device, scene, corners);
      if (colours.size() <= id) colours.resize(id + 1, v->colour);
      colours[id] = v->colour;
    }
  } catch (...) {
    rtcReleaseScene(scene);
    throw;
  }
  rtcCommitScene(scene);
  if (!box.isEmpty()) {
    sphere.head<3>() = box.center();
    sphere[3] = 0.5 * box.diagonal().norm();
  }
  return scene;
}

}  // namespace

std::vector<Eigen::Vector3d> visualTriangles(const VisualGeometry& v) {
  const CollisionGeometry& g = v.shape;
  if (g.type != CollisionGeometry::Type::kMesh && g.size.maxCoeff() <= 0.0) return {};  // size 0
  std::vector<Eigen::Vector3d> local;
  switch (g.type) {
    case CollisionGeometry::Type::kBox:
      local = boxSurface(g.size);
      break;
    case CollisionGeometry::Type::kCylinder:
      local = cylinderSurface(g.size.x(), g.size.y());
      break;
    case CollisionGeometry::Type::kSphere:
      local = ellipsoidSurface(Eigen::Vector3d::Constant(g.size.x()));
      break;
    case CollisionGeometry::Type::kMesh:
      if (v.mesh_path.empty()) throw ModelError(v.mesh_error);
      try {
        local = loadMeshTriangles(v.mesh_path);
      } catch (const ModelError& e) {
        throw ModelError("link '" + v.link + "': visual mesh '" + g.mesh_uri + "': " + e.what());
      }
      for (Eigen::Vector3d& c : local) c = c.cwiseProduct(g.size);
      break;
  }
  for (Eigen::Vector3d& c : local) c = g.origin * c;
  return local;
}

CameraRobot::CameraRobot(RTCDeviceTy* device, const RobotModel& robot,
                         const std::string& hidden_link) {
  bodies_.resize(robot.bodies().size());
  try {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      std::vector<const VisualGeometry*> all, own;
      for (const VisualGeometry& v : robot.bodies()[b].visuals) {
        all.push_back(&v);
        if (v.link != hidden_link) own.push_back(&v);
      }
      Body& body = bodies_[b];
      body.all = visualScene(device, all, body.colours, body.sphere);
      if (own.size() == all.size()) {
        body.own = body.all;
        body.own_colours = body.colours;
        body.own_sphere = body.sphere;
      } else {
        body.own = visualScene(device, own, body.own_colours, body.own_sphere);
      }
    }
  } catch (...) {
    release();
    throw;
  }
}

CameraRobot::~CameraRobot() { release(); }

void CameraRobot::release() {
  for (Body& body : bodies_) {
    if (body.own && body.own != body.all) rtcReleaseScene(body.own);
    if (body.all) rtcReleaseScene(body.all);
    body.own = body.all = nullptr;
  }
}

}  // namespace jetbot_rl
