#include "jetbot_rl/world/gazebo/mesh_loader.h"

#include <LinearMath/btConvexHullComputer.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>

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

/// The file at `path` read by `importer` (polygons triangulated with `faces`); throws ModelError
/// naming it.
const aiScene& importMesh(Assimp::Importer& importer, const std::string& path, bool faces) {
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ModelError("mesh file '" + path + "' cannot be read: it " + problem);
  }
  // ROS tools (RViz, Gazebo) read COLLADA in its own axes; only its unit is applied.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const unsigned flags = aiProcess_JoinIdenticalVertices | (faces ? aiProcess_Triangulate : 0u);
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || !scene->mRootNode) {
    const std::string why = importer.GetErrorString();
    throw ModelError("mesh file '" + path + "' cannot be read" + (why.empty() ? "" : ": " + why));
  }
  return *scene;
}

/// Throws ModelError naming `path` when `points` is empty or holds a non-finite point.
void checkPoints(const std::vector<Eigen::Vector3d>& points, const std::string& path,
                 const char* what) {
  for (const auto& p : points) {
    if (!p.allFinite()) throw ModelError("mesh file '" + path + "' has a non-finite vertex");
  }
  if (points.empty()) throw ModelError("mesh file '" + path + "' holds no " + what);
}

/// The vertices (or triangle corners) of the file at `path`; throws ModelError naming it.
std::vector<Eigen::Vector3d> readMesh(const std::string& path, bool faces) {
  Assimp::Importer importer;
  const aiScene& scene = importMesh(importer, path, faces);
  std::vector<Eigen::Vector3d> points;
  collectVertices(scene, *scene.mRootNode, aiMatrix4x4(), faces, points);
  checkPoints(points, path, faces ? "triangles" : "vertices");
  return points;
}

/// Appends every triangle under `node` to the part of its mesh's material, with its corners'
/// texture coordinates.
void collectParts(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                  std::vector<MeshPart>& parts) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    MeshPart& part = parts[std::min<std::size_t>(mesh.mMaterialIndex, parts.size() - 1)];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      for (unsigned k = 0; k < 3; ++k) {
        const unsigned i = face.mIndices[k];
        const aiVector3D p = transform * mesh.mVertices[i];
        part.triangles.emplace_back(p.x, p.y, p.z);
        // A mesh without coordinates shows a texture's first texel.
        const aiVector3D uv = mesh.HasTextureCoords(0) ? mesh.mTextureCoords[0][i] : aiVector3D();
        part.uv.emplace_back(uv.x, uv.y);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collectParts(scene, *node.mChildren[c], transform, parts);
  }
}

/// The file a material's texture name `name` means, read from the mesh at `mesh_path`: as given
/// (a relative name against the mesh's folder), else its base name in the model's
/// `materials/textures/` (Gazebo adds that folder to its resource paths); "" when neither exists.
std::string findTexture(std::string name, const std::string& mesh_path) {
  namespace fs = std::filesystem;
  static const std::string kFile = "file://";
  if (name.compare(0, kFile.size(), kFile) == 0) name = name.substr(kFile.size());
  if (name.empty() || name[0] == '*') return "";  // embedded in the mesh file: not read
  const fs::path folder = fs::path(mesh_path).parent_path();
  std::error_code error;
  for (const fs::path& candidate :
       {fs::path(name).is_absolute() ? fs::path(name) : folder / name,
        folder.parent_path() / "materials" / "textures" / fs::path(name).filename()}) {
    if (fs::exists(candidate, error)) return candidate.lexically_normal().string();
  }
  return "";
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

std::vector<MeshPart> loadMeshParts(const std::string& path) {
  Assimp::Importer importer;
  const aiScene& scene = importMesh(importer, path, true);
  std::vector<MeshPart> parts(std::max(1u, scene.mNumMaterials));
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    const aiMaterial& material = *scene.mMaterials[i];
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
        std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME) {
      continue;  // assimp's own, for a file that names no material
    }
    aiColor3D diffuse;
    if (material.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
      parts[i].colour = Eigen::Vector3f(diffuse.r, diffuse.g, diffuse.b);
    }
    aiString texture;
    if (material.GetTextureCount(aiTextureType_DIFFUSE) > 0 &&
        material.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS) {
      parts[i].texture_as_given = texture.C_Str();
      parts[i].texture = findTexture(parts[i].texture_as_given, path);
    }
  }
  collectParts(scene, *scene.mRootNode, aiMatrix4x4(), parts);
  std::vector<Eigen::Vector3d> all;
  for (const MeshPart& part : parts)
    all.insert(all.end(), part.triangles.begin(), part.triangles.end());
  checkPoints(all, path, "triangles");
  parts.erase(std::remove_if(parts.begin(), parts.end(),
                             [](const MeshPart& p) { return p.triangles.empty(); }),
              parts.end());
  return parts;
}

}  // namespace jetbot_rl
