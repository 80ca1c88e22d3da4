#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace jetbot_rl {

/**
 * Turns a mesh URI that is neither a plain path nor `file://` (e.g. `package://pkg/mesh.stl`) into
 * a file path. Returns "" or throws when it cannot; the core stays ROS-free, so the ROS adapter
 * passes one that resolves `package://`.
 */
using MeshResolver = std::function<std::string(const std::string& uri)>;

/// File path of a URDF mesh URI: a plain path is used as is, `file://` is stripped, any other
/// scheme goes through `resolver`. Throws ModelError naming the URI when it cannot be resolved.
std::string resolveMeshUri(const std::string& uri, const MeshResolver& resolver);

/**
 * Vertices of the convex hull of every mesh in a file that assimp reads (STL, COLLADA, OBJ, ...),
 * node transforms applied, in the file's units and axes [m] (a COLLADA `<unit>` is applied, its
 * `<up_axis>` ignored, as RViz and Gazebo do). Throws ModelError naming the path when the file
 * cannot be read or holds no vertices.
 */
std::vector<Eigen::Vector3d> loadMeshHull(const std::string& path);

/// The triangles of every mesh in the file (polygons triangulated), three corners each, read as
/// loadMeshHull() reads the file [m]. Throws ModelError naming the path.
std::vector<Eigen::Vector3d> loadMeshTriangles(const std::string& path);

/// The triangles of a mesh file that share one material, with what the material says of them.
struct MeshPart {
  std::vector<Eigen::Vector3d> triangles;  ///< Three corners per triangle [m].
  std::optional<Eigen::Vector3f> colour;   ///< Its diffuse RGB; none: the file gives none.
  /// Its diffuse texture file, resolved against the mesh's folder (else its base name in the
  /// model's `materials/textures/`, where Gazebo also looks); "" without one. `texture_as_given`:
  /// the name in the file (also when it is not found).
  std::string texture, texture_as_given;
  /// Texture coordinates per corner (0, 0 where the file has none), for its texture or one a
  /// material script gives.
  std::vector<Eigen::Vector2f> uv;
};

/// loadMeshTriangles(), the triangles grouped by their material (assimp's default material, of a
/// file that names none, gives no colour). ModelError naming the path.
std::vector<MeshPart> loadMeshParts(const std::string& path);

}  // namespace jetbot_rl
