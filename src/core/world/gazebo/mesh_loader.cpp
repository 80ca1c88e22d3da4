#include "jetbot_rl/world/gazebo/mesh_loader.h"

#include <LinearMath/btConvexHullComputer.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

/// Every vertex of the scene's meshes (node transforms applied), or with `faces` the corners of
/// every triangle, three per triangle.
void collectVertices(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                     bool faces, std::vector<Eigen::Vector3d>& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  const auto add = [&](const aiVector3D& v) {
    const aiVector3D p = transform * v;
    out.emplace_back(p.x, p.y, p.z);
  };
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    if (!faces) {
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) add(mesh.mVertices[v]);
      continue;
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines (triangulated otherwise)
      for (unsigned k = 0; k < 3; ++k) add(mesh.mVertices[face.mIndices[k]]);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collectVertices(scene, *node.mChildren[c], transform, faces, out);
  }
}

/// The vertices (or triangle corners) of the file at `path`; throws ModelError naming it.
std::vector<Eigen::Vector3d> readMesh(const std::string& path, bool faces) {
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ModelError("mesh file '" + path + "' cannot be read: it " + problem);
  }
  Assimp::Importer importer;
  // ROS tools (RViz, Gazebo) read COLLADA in its own axes; only its unit is applied.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const unsigned flags = aiProcess_JoinIdenticalVertices | (faces ? aiProcess_Triangulate : 0u);
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || !scene->mRootNode) {
    const std::string why = importer.GetErrorString();
    throw ModelError("mesh file '" + path + "' cannot be read" + (why.empty() ? "" : ": " + why));
  }
  std::vector<Eigen::Vector3d> points;
  collectVertices(*scene, *scene->mRootNode, aiMatrix4x4(), faces, points);
  for (const auto& p : points) {
    if (!p.allFinite()) throw ModelError("mesh file '" + path + "' has a non-finite vertex");
  }
  if (points.empty()) {
    throw ModelError("mesh file '" + path + "' holds no " + (faces ? "triangles" : "vertices"));
  }
  return points;
}

/// The points among `points` that span their convex hull (all of them if the hull fails).
std::vector<Eigen::Vector3d> hullVertices(const std::vector<Eigen::Vector3d>& points) {
  btConvexHullComputer hull;
  const double* coords = points.front().data();
  if (hull.compute(coords, static_cast<int>(sizeof(Eigen::Vector3d)),
                   static_cast<int>(points.size()), 0, 0) < 0 ||
      hull.original_vertex_index.size() == 0) {
    return points;
  }
  std::vector<Eigen::Vector3d> kept;
  kept.reserve(hull.original_vertex_index.size());
  for (int i = 0; i < hull.original_vertex_index.size(); ++i) {
    kept.push_back(points[hull.original_vertex_index[i]]);
  }
  return kept;
}

}  // namespace

std::string resolveMeshUri(const std::string& uri, const MeshResolver& resolver) {
  static const std::string kFile = "file://";
  if (uri.empty()) throw ModelError("mesh filename is empty");
  if (uri.compare(0, kFile.size(), kFile) == 0) return uri.substr(kFile.size());
  const auto scheme_end = uri.find("://");
  if (scheme_end == std::string::npos) return uri;
  const std::string scheme = uri.substr(0, scheme_end);
  if (!resolver) {
    throw ModelError("mesh '" + uri + "': " + scheme +
                     ":// URIs need a resolver (the ROS adapter resolves package://); give a file "
                     "path or file:// URI to the core");
  }
  std::string path;
  try {
    path = resolver(uri);
  } catch (const std::exception& e) {
    throw ModelError("mesh '" + uri + "' could not be resolved: " + e.what());
  }
  if (path.empty()) throw ModelError("mesh '" + uri + "' could not be resolved");
  if (path.compare(0, kFile.size(), kFile) == 0) path = path.substr(kFile.size());
  return path;
}

std::vector<Eigen::Vector3d> loadMeshHull(const std::string& path) {
  return hullVertices(readMesh(path, false));
}

std::vector<Eigen::Vector3d> loadMeshTriangles(const std::string& path) {
  return readMesh(path, true);
}

}  // namespace jetbot_rl
