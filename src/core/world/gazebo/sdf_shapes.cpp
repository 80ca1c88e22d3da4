#include "world/gazebo/sdf_shapes.h"

#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/package_path.h"
#include "world/gazebo/sdf_prepass.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {
namespace {

/// A `<polyline>` (sdformat 12 has no class for it: read from its element). False if none.
bool polyline(const sdf::Geometry& g, std::vector<Eigen::Vector3d>& out) {
  const sdf::ElementPtr geometry = g.Element();
  if (!geometry || !geometry->HasElement("polyline")) return false;
  for (sdf::ElementPtr p = geometry->GetElement("polyline"); p; p = p->GetNextElement("polyline")) {
    std::vector<Eigen::Vector2d> points;
    for (sdf::ElementPtr q = p->HasElement("point") ? p->GetElement("point") : nullptr; q;
         q = q->GetNextElement("point")) {
      const auto v = q->Get<ignition::math::Vector2d>();
      if (!(std::abs(v.X()) <= kMaxShapeSize && std::abs(v.Y()) <= kMaxShapeSize)) {
        std::ostringstream text;
        text << "its polyline point (" << v.X() << ", " << v.Y() << ") lies beyond "
             << kMaxShapeSize << " m of its origin";
        throw ConfigError(text.str());
      }
      points.emplace_back(v.X(), v.Y());
    }
    if (const double height = p->Get<double>("height");
        !(height > 0.0 && height <= kMaxShapeSize)) {
      std::ostringstream text;
      text << "its polyline height " << height << " must be in (0, " << kMaxShapeSize << "] m";
      throw ConfigError(text.str());
    }
    const auto surface = polylineSurface(points, p->Get<double>("height"));
    out.insert(out.end(), surface.begin(), surface.end());
  }
  return !out.empty();
}

}  // namespace

Eigen::Isometry3d toEigen(const ignition::math::Pose3d& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  t.linear() = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z())
                   .normalized()
                   .toRotationMatrix();
  return t;
}

std::string whereIs(const sdf::ElementPtr& element, const std::string& world_path) {
  if (!element) return world_path;
  const std::string& file = element->FilePath();
  std::string where = file.rfind('/', 0) == 0 ? file : world_path;
  if (const std::optional<int> line = element->LineNumber()) where += ":" + std::to_string(*line);
  return where;
}

std::string sdfPlacementProblem(const sdf::Geometry& g, const Eigen::Isometry3d& pose) {
  if (!pose.translation().allFinite() ||
      pose.translation().cwiseAbs().maxCoeff() > kMaxShapeDistance) {
    std::ostringstream s;
    s << "its pose in the world (" << pose.translation().transpose() << ") must lie within "
      << kMaxShapeDistance << " m of the origin on every axis";
    return s.str();
  }
  const auto sized = [](const char* what, std::initializer_list<double> values) {
    for (double v : values) {
      if (!(v > 0.0 && v <= kMaxShapeSize)) {
        std::ostringstream s;
        s << what << " " << v << " must be in (0, " << kMaxShapeSize << "] m";
        return s.str();
      }
    }
    return std::string();
  };
  switch (g.Type()) {
    case sdf::GeometryType::BOX: {
      const auto b = g.BoxShape()->Size();
      return sized("its box size", {b.X(), b.Y(), b.Z()});
    }
    case sdf::GeometryType::CYLINDER:
      return sized("its cylinder radius and length",
                   {g.CylinderShape()->Radius(), g.CylinderShape()->Length()});
    case sdf::GeometryType::SPHERE:
      return sized("its sphere radius", {g.SphereShape()->Radius()});
    case sdf::GeometryType::ELLIPSOID: {
      const auto a = g.EllipsoidShape()->Radii();
      return sized("its ellipsoid radii", {a.X(), a.Y(), a.Z()});
    }
    case sdf::GeometryType::CAPSULE:
      return sized("its capsule radius and length",
                   {g.CapsuleShape()->Radius(), g.CapsuleShape()->Length()});
    default:
      return "";
  }
}

namespace {

/// The file of mesh `m` (a URI resolved as Gazebo 11 resolves it, a relative path against the
/// SDF file that names it); throws Error.
std::string sdfMeshPath(const sdf::Mesh& m, const std::string& world_path,
                        const MeshResolver& resolver) {
  std::string path = resolveMeshUri(m.Uri(), [&](const std::string& u) {
    if (u.rfind("model://", 0) == 0) {
      const std::string found = findGazeboModel(u);
      if (found.empty()) throw ConfigError("no model folder of that name");
      return found;
    }
    if (resolver) return resolver(u);
    const std::string found = findPackageUri(u);
    if (found.empty()) throw ConfigError("no such package on ROS_PACKAGE_PATH");
    return found;
  });
  if (!path.empty() && path[0] != '/') {  // relative to the SDF file that names it
    // Read from a string (sdf_prepass.h), the world's own models have no file path.
    const std::string& from = m.FilePath().rfind('/', 0) == 0 ? m.FilePath() : world_path;
    const auto slash = from.rfind('/');
    if (slash != std::string::npos) path = from.substr(0, slash + 1) + path;
  }
  return path;
}

/// Applies mesh `m`'s `<scale>` to `triangles`; ConfigError for a vertex beyond the bounds.
void scaleMesh(const sdf::Mesh& m, std::vector<Eigen::Vector3d>& triangles) {
  const auto s = m.Scale();
  const Eigen::Vector3d scale(s.X(), s.Y(), s.Z());
  for (Eigen::Vector3d& p : triangles) {
    p = p.cwiseProduct(scale);
    if (!(p.cwiseAbs().maxCoeff() <= kMaxShapeSize)) {
      std::ostringstream s;
      s << "a vertex of mesh '" << m.Uri() << "' at scale " << scale.transpose() << " lies at ("
        << p.transpose() << "), beyond " << kMaxShapeSize << " m of its origin";
      throw ConfigError(s.str());
    }
  }
}

void noteSubmesh(const sdf::Mesh& m, const std::string& name, std::vector<std::string>& notes) {
  if (!m.Submesh().empty()) {
    notes.push_back("submesh choice of '" + name + "' (the whole mesh is used)");
  }
}

}  // namespace

std::vector<Eigen::Vector3d> sdfMeshTriangles(const sdf::Mesh& m, const std::string& world_path,
                                              const MeshResolver& resolver, const std::string& name,
                                              std::vector<std::string>& notes) {
  try {
    std::vector<Eigen::Vector3d> triangles =
        loadMeshTriangles(sdfMeshPath(m, world_path, resolver));
    scaleMesh(m, triangles);
    noteSubmesh(m, name, notes);
    return triangles;
  } catch (const Error& e) {
    throw ConfigError(e.what());
  }
}

std::vector<MeshPart> sdfMeshParts(const sdf::Mesh& m, const std::string& world_path,
                                   const MeshResolver& resolver, const std::string& name,
                                   std::vector<std::string>& notes) {
  try {
    std::vector<MeshPart> parts = loadMeshParts(sdfMeshPath(m, world_path, resolver));
    for (MeshPart& part : parts) scaleMesh(m, part.triangles);
    noteSubmesh(m, name, notes);
    return parts;
  } catch (const Error& e) {
    throw ConfigError(e.what());
  }
}

std::vector<Eigen::Vector3d> sdfSurface(const sdf::Geometry& g, const std::string& world_path,
                                        const MeshResolver& resolver, const std::string& name,
                                        std::vector<std::string>& notes) {
  std::vector<Eigen::Vector3d> local;
  switch (g.Type()) {
    case sdf::GeometryType::BOX: {
      const auto s = g.BoxShape()->Size();
      return boxSurface(Eigen::Vector3d(s.X(), s.Y(), s.Z()));
    }
    case sdf::GeometryType::CYLINDER:
      return cylinderSurface(g.CylinderShape()->Radius(), g.CylinderShape()->Length());
    case sdf::GeometryType::SPHERE:
      return ellipsoidSurface(Eigen::Vector3d::Constant(g.SphereShape()->Radius()));
    case sdf::GeometryType::ELLIPSOID: {
      const auto a = g.EllipsoidShape()->Radii();
      return ellipsoidSurface(Eigen::Vector3d(a.X(), a.Y(), a.Z()));
    }
    case sdf::GeometryType::CAPSULE: {
      const double radius = g.CapsuleShape()->Radius(), length = g.CapsuleShape()->Length();
      local = cylinderSurface(radius, length);
      for (double end : {-0.5 * length, 0.5 * length}) {
        const auto cap =
            ellipsoidSurface(Eigen::Vector3d::Constant(radius), Eigen::Vector3d(0, 0, end));
        local.insert(local.end(), cap.begin(), cap.end());
      }
      return local;
    }
    case sdf::GeometryType::MESH:
      return sdfMeshTriangles(*g.MeshShape(), world_path, resolver, name, notes);
    case sdf::GeometryType::PLANE:
    case sdf::GeometryType::HEIGHTMAP:
      return local;
    default:
      polyline(g, local);
      return local;
  }
}

}  // namespace jetbot_rl
