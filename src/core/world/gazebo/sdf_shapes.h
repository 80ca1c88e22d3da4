#pragma once
// The surfaces of SDF geometry (a <collision>'s or a <visual>'s) as triangles in its own frame,
// with the bounds every shape of a Gazebo world is held to, and what the reader shares about SDF
// elements (poses, file and line).
#include <Eigen/Geometry>
#include <sdf/sdf.hh>
#include <string>
#include <vector>

#include "jetbot_rl/world/gazebo/mesh_loader.h"

namespace jetbot_rl {

// What a shape may measure and where it may lie [m]: beyond, it is refused naming it (a size of
// 1e300 would take the cut's loops for ever; a shape 100 km out, a grid of 4e12 cells).
constexpr double kMaxShapeSize = 1000.0;
constexpr double kMaxShapeDistance = 10000.0;

/// An sdformat pose as an Eigen transform.
Eigen::Isometry3d toEigen(const ignition::math::Pose3d& p);

/// "FILE:LINE" of an SDF element (the world's file when sdformat read it from a string).
std::string whereIs(const sdf::ElementPtr& element, const std::string& world_path);

/// Why `g` at `pose` (in the world) is refused, or "": its pose beyond kMaxShapeDistance of
/// the origin on an axis, or a size outside (0, kMaxShapeSize].
std::string sdfPlacementProblem(const sdf::Geometry& g, const Eigen::Isometry3d& pose);

/// The triangles of mesh `m` (assimp), scaled, its URI resolved as Gazebo does (`model://`,
/// `file://`, relative to the SDF file naming it, else through `resolver` or ROS_PACKAGE_PATH);
/// a submesh choice is noted in `notes` (the whole mesh is used). ConfigError saying why.
std::vector<Eigen::Vector3d> sdfMeshTriangles(const sdf::Mesh& m, const std::string& world_path,
                                              const MeshResolver& resolver, const std::string& name,
                                              std::vector<std::string>& notes);

/// sdfMeshTriangles() grouped by the mesh file's own materials (loadMeshParts()).
std::vector<MeshPart> sdfMeshParts(const sdf::Mesh& m, const std::string& world_path,
                                   const MeshResolver& resolver, const std::string& name,
                                   std::vector<std::string>& notes);

/// The surface of `g` in its own frame: boxes, cylinders, spheres, ellipsoids, capsules,
/// meshes and <polyline> extrusions; empty for planes, heightmaps and empty geometry.
/// ConfigError for a polyline or mesh beyond the bounds, or a mesh that cannot be read.
std::vector<Eigen::Vector3d> sdfSurface(const sdf::Geometry& g, const std::string& world_path,
                                        const MeshResolver& resolver, const std::string& name,
                                        std::vector<std::string>& notes);

}  // namespace jetbot_rl
