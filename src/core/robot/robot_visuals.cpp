#include "robot/robot_visuals.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/urdf_errors.h"
#include "robot/urdf_pose.h"

namespace jetbot_rl {

bool setPrimitive(const urdf::Geometry& geometry, CollisionGeometry& g) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      g.type = CollisionGeometry::Type::kBox;
      g.size << box.dim.x, box.dim.y, box.dim.z;
      return true;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      g.type = CollisionGeometry::Type::kCylinder;
      g.size << cylinder.radius, cylinder.length, 0.0;
      return true;
    }
    case urdf::Geometry::SPHERE:
      g.type = CollisionGeometry::Type::kSphere;
      g.size << static_cast<const urdf::Sphere&>(geometry).radius, 0.0, 0.0;
      return true;
    default:
      return false;
  }
}

VisualGeometry visualGeometry(const urdf::Link& link, const urdf::Visual& visual,
                              const Eigen::Isometry3d& offset, const MeshResolver& resolver) {
  VisualGeometry v;
  v.link = link.name;
  CollisionGeometry& g = v.shape;
  g.origin = offset * toIsometry(visual.origin);
  if (!visual.geometry) throw ModelError(linkError(link.name, "visual without geometry"));
  if (!setPrimitive(*visual.geometry, g)) {
    if (visual.geometry->type != urdf::Geometry::MESH) {
      throw ModelError(linkError(link.name, "unsupported visual geometry type"));
    }
    const auto& mesh = static_cast<const urdf::Mesh&>(*visual.geometry);
    g.type = CollisionGeometry::Type::kMesh;
    g.mesh_uri = mesh.filename;
    g.size << mesh.scale.x, mesh.scale.y, mesh.scale.z;
    try {
      v.mesh_path = resolveMeshUri(mesh.filename, resolver);
    } catch (const ModelError& e) {
      v.mesh_error = linkError(link.name, std::string("visual ") + e.what());
    }
  }
  // A visual of size 0 draws nothing; a negative or non-finite one is an error in the file.
  if (!g.size.allFinite() || (g.type != CollisionGeometry::Type::kMesh && g.size.minCoeff() < 0)) {
    std::ostringstream s;
    s << "visual shape dimensions must be finite and not negative, got " << g.size.transpose();
    throw ModelError(linkError(link.name, s.str()));
  }
  if (visual.material && !visual.material->texture_filename.empty()) {
    const std::string& name = visual.material->texture_filename;
    try {
      v.texture_path = resolveMeshUri(name, resolver);
    } catch (const ModelError& e) {
      v.texture_error = linkError(link.name, "visual texture '" + name + "': " + e.what());
    }
  }
  if (visual.material) {
    const urdf::Color& c = visual.material->color;
    const Eigen::Vector3f rgb(c.r, c.g, c.b);
    // urdfdom leaves a material without <color> (a texture only) at 0 0 0 0: keep the grey.
    if (rgb.allFinite() && c.a > 0.0f) {
      v.colour = rgb.cwiseMax(0.0f).cwiseMin(1.0f);
      v.coloured = true;
    }
  }
  return v;
}

}  // namespace jetbot_rl
