#include "sensors/camera_robot.h"

#include <embree3/rtcore.h>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/world/gazebo/mesh_loader.h"
#include "sensors/embree_geometry.h"
#include "world/primitive_uv.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {
namespace {

/// A scene of `visuals` (each surface a geometry, its material in `materials`), or nullptr for
/// none; `sphere`: (centre, radius) of a sphere holding them all.
RTCScene visualScene(RTCDevice device, const std::vector<const VisualGeometry*>& visuals,
                     TextureCache& textures, std::vector<SurfaceMaterial>& materials,
                     Eigen::Vector4d& sphere) {
  if (visuals.empty()) return nullptr;
  Eigen::AlignedBox3d box;
  RTCScene scene = rtcNewScene(device);
  if (!scene) throwEmbree(device, "rtcNewScene");
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  try {
    for (const VisualGeometry* v : visuals) {
      for (auto& [material, corners] : visualSurfaces(*v, textures)) {
        if (corners.empty()) continue;
        for (const Eigen::Vector3d& c : corners) box.extend(c);
        const unsigned id = attachTriangles(device, scene, corners);
        if (materials.size() <= id) materials.resize(id + 1);
        materials[id] = std::move(material);
      }
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

/// Visual `v`'s surfaces `surfaces` (in its shape's own frame) as one, covered by its URDF
/// texture: a mesh by its coordinates, a primitive across its faces.
std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>> urdfTextured(
    const VisualGeometry& v,
    const std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>>& surfaces,
    TextureCache& textures) {
  if (v.texture_path.empty()) throw ModelError(v.texture_error);
  const CollisionGeometry& g = v.shape;
  std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>> out;
  SurfaceMaterial& m = out.first;
  try {
    auto [at, first] = textures.images.try_emplace(v.texture_path);
    if (first) at->second = loadTextureImage(v.texture_path, &textures.bytes);
    m.texture = at->second;
  } catch (const ModelError& e) {
    throw ModelError("link '" + v.link + "': visual " + e.what());
  }
  switch (g.type) {
    case CollisionGeometry::Type::kMesh:
      for (MeshPart& part : loadMeshParts(v.mesh_path)) {  // read before: it can be read
        out.second.insert(out.second.end(), part.triangles.begin(), part.triangles.end());
        m.uv.insert(m.uv.end(), part.uv.begin(), part.uv.end());
      }
      break;
    case CollisionGeometry::Type::kBox:
      out.second = surfaces.front().second;
      m.uv = primitiveUv(UvShape::kBox, g.size, out.second);
      break;
    case CollisionGeometry::Type::kCylinder:
      out.second = surfaces.front().second;
      m.uv = primitiveUv(UvShape::kCylinder, g.size, out.second);
      break;
    case CollisionGeometry::Type::kSphere:
      out.second = surfaces.front().second;
      m.uv = primitiveUv(UvShape::kSphere, g.size, out.second);
      break;
  }
  return out;
}

}  // namespace

std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> visualSurfaces(
    const VisualGeometry& v, TextureCache& textures) {
  const CollisionGeometry& g = v.shape;
  if (g.type != CollisionGeometry::Type::kMesh && g.size.maxCoeff() <= 0.0) return {};  // size 0
  std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> out(1);
  out[0].first.colour = v.colour;
  std::vector<Eigen::Vector3d>& local = out[0].second;
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
    case CollisionGeometry::Type::kMesh: {
      if (v.mesh_path.empty()) throw ModelError(v.mesh_error);
      try {
        if (v.coloured) {
          local = loadMeshTriangles(v.mesh_path);
          break;
        }
        out.clear();
        for (MeshPart& part : loadMeshParts(v.mesh_path)) {
          SurfaceMaterial m;
          if (part.colour) m.colour = part.colour->cwiseMax(0.0f).cwiseMin(1.0f);
          if (!part.texture_as_given.empty() && part.texture.empty()) {
            throw ModelError("texture '" + part.texture_as_given + "' not found");
          }
          if (!part.texture.empty()) {
            auto [at, first] = textures.images.try_emplace(part.texture);
            if (first) at->second = loadTextureImage(part.texture, &textures.bytes);
            m.texture = at->second;
            m.uv = std::move(part.uv);
          }
          out.emplace_back(std::move(m), std::move(part.triangles));
        }
      } catch (const ModelError& e) {
        throw ModelError("link '" + v.link + "': visual mesh '" + g.mesh_uri + "': " + e.what());
      }
      break;
    }
  }
  if (!v.texture_path.empty() || !v.texture_error.empty()) out = {urdfTextured(v, out, textures)};
  for (auto& [material, corners] : out) {
    for (Eigen::Vector3d& c : corners) {
      if (g.type == CollisionGeometry::Type::kMesh) c = c.cwiseProduct(g.size);
      c = g.origin * c;
    }
  }
  return out;
}

CameraRobot::CameraRobot(RTCDeviceTy* device, const RobotModel& robot,
                         const std::string& hidden_link) {
  bodies_.resize(robot.bodies().size());
  TextureCache textures;
  try {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      std::vector<const VisualGeometry*> all, own;
      for (const VisualGeometry& v : robot.bodies()[b].visuals) {
        all.push_back(&v);
        if (v.link != hidden_link) own.push_back(&v);
      }
      Body& body = bodies_[b];
      body.all = visualScene(device, all, textures, body.materials, body.sphere);
      if (own.size() == all.size()) {
        body.own = body.all;
        body.own_materials = body.materials;
        body.own_sphere = body.sphere;
      } else {
        body.own = visualScene(device, own, textures, body.own_materials, body.own_sphere);
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
