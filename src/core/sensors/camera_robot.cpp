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

/// The texture at `path` through `textures` (read at its first use); ModelError saying why not.
std::shared_ptr<const TextureImage> cachedTexture(const std::string& path, TextureCache& textures) {
  auto [at, first] = textures.images.try_emplace(path);
  if (first) {
    try {
      at->second = loadTextureImage(path, &textures.bytes);
    } catch (...) {
      textures.images.erase(at);
      throw;
    }
  }
  return at->second;
}

}  // namespace

std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> visualSurfaces(
    const VisualGeometry& v, TextureCache& textures) {
  const CollisionGeometry& g = v.shape;
  if (g.type != CollisionGeometry::Type::kMesh && g.size.maxCoeff() <= 0.0) return {};  // size 0
  if (!v.texture_error.empty()) throw ModelError(v.texture_error);
  std::shared_ptr<const TextureImage> urdf_texture;  // covers the whole visual
  if (!v.texture_path.empty()) {
    try {
      urdf_texture = cachedTexture(v.texture_path, textures);
    } catch (const ModelError& e) {
      throw ModelError("link '" + v.link + "': visual " + e.what());
    }
  }
  std::vector<std::pair<SurfaceMaterial, std::vector<Eigen::Vector3d>>> out(1);
  out[0].first.colour = v.colour;
  out[0].first.texture = urdf_texture;
  std::vector<Eigen::Vector3d>& local = out[0].second;
  std::vector<Eigen::Vector2f>& uv = out[0].first.uv;
  switch (g.type) {
    case CollisionGeometry::Type::kBox:
      local = boxSurface(g.size);
      if (urdf_texture) uv = primitiveUv(UvShape::kBox, g.size, local);
      break;
    case CollisionGeometry::Type::kCylinder:
      local = cylinderSurface(g.size.x(), g.size.y());
      if (urdf_texture) uv = primitiveUv(UvShape::kCylinder, g.size, local);
      break;
    case CollisionGeometry::Type::kSphere:
      local = ellipsoidSurface(Eigen::Vector3d::Constant(g.size.x()));
      if (urdf_texture) uv = primitiveUv(UvShape::kSphere, g.size, local);
      break;
    case CollisionGeometry::Type::kMesh: {
      if (v.mesh_path.empty()) throw ModelError(v.mesh_error);
      try {
        if (v.coloured && !urdf_texture) {
          local = loadMeshTriangles(v.mesh_path);
          break;
        }
        std::vector<MeshPart> parts = loadMeshParts(v.mesh_path);
        if (urdf_texture) {  // the URDF's texture by the mesh's coordinates
          for (MeshPart& part : parts) {
            local.insert(local.end(), part.triangles.begin(), part.triangles.end());
            uv.insert(uv.end(), part.uv.begin(), part.uv.end());
          }
          break;
        }
        out.clear();  // the file's own materials
        for (MeshPart& part : parts) {
          SurfaceMaterial m;
          if (part.colour) m.colour = part.colour->cwiseMax(0.0f).cwiseMin(1.0f);
          if (!part.texture_as_given.empty() && part.texture.empty()) {
            throw ModelError("texture '" + part.texture_as_given + "' not found");
          }
          if (!part.texture.empty()) {
            m.texture = cachedTexture(part.texture, textures);
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
