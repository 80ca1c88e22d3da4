#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/robot/urdf_gazebo_blocks.h"
#include "jetbot_rl/world/gazebo/mesh_loader.h"

namespace jetbot_rl {

/// One collision primitive, expressed in its body's link frame.
struct CollisionGeometry {
  enum class Type { kBox, kCylinder, kSphere, kMesh };
  Type type = Type::kBox;
  /// Box: full extents x, y, z [m]; cylinder: radius, length along its z [m]; sphere: radius [m];
  /// mesh: the URDF scale.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  /// Pose of the primitive in the body's link frame.
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  /// Mesh: the vertices of its convex hull, scaled, in the primitive's frame [m].
  std::vector<Eigen::Vector3d> vertices;
  /// Mesh: the filename as the URDF gives it.
  std::string mesh_uri;
};

/// One visual element (URDF <visual>), expressed in its body's link frame: what a camera sees of
/// the robot (docs/camera.md).
struct VisualGeometry {
  /// Its shape: type, size and origin as a collision's; a mesh keeps its URI and scale (`size`)
  /// and is read when a camera needs its triangles (mesh_path), not at parse time.
  CollisionGeometry shape;
  std::string link;  ///< The URDF link it belongs to.
  /// Diffuse RGB in [0, 1]: its material's colour (inline or named at the robot's top level),
  /// else grey.
  Eigen::Vector3f colour{0.7f, 0.7f, 0.7f};
  /// Its URDF material gave `colour`; without, a mesh shows its file's own materials.
  bool coloured = false;
  /// Its URDF material's `<texture filename>`, resolved: drawn instead of the colours, on a mesh
  /// by its texture coordinates, on a box, cylinder or sphere across its faces. Empty without
  /// one, or when it could not be resolved (texture_error).
  std::string texture_path;
  std::string texture_error;  ///< Why texture_path is empty though a texture is named.
  std::string mesh_path;   ///< Mesh: the file, resolved; empty when it could not be (mesh_error).
  std::string mesh_error;  ///< Mesh: why mesh_path is empty, naming the link and the URI.
};

/// A link rigidly attached to a body by fixed joints (kept for tf and visualisation).
struct AttachedLink {
  std::string name;
  /// Pose of this link in the body's link frame.
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  /// The URDF parent link's name (of the joint above this link); empty for the robot's root.
  std::string parent;
};

/// One rigid body of the robot: a moving URDF link with every fixed-joint descendant merged in.
struct BodyModel {
  std::string link_name;
  /// Index of the parent body, -1 for the root.
  int parent = -1;
  /// Joint from the parent body (empty for the root).
  std::string joint_name;
  /// True for a revolute joint (limits apply), false for continuous or the root.
  bool has_position_limits = false;
  /// Pose of this link frame in the parent body's link frame at zero joint angle.
  Eigen::Isometry3d joint_origin = Eigen::Isometry3d::Identity();
  /// Unit joint axis in this link frame.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  double lower = 0.0;           ///< Joint lower limit [rad] (revolute only).
  double upper = 0.0;           ///< Joint upper limit [rad] (revolute only).
  double velocity_limit = 0.0;  ///< Joint velocity limit [rad/s].
  double effort_limit = 0.0;    ///< Joint effort limit [N m].
  double mass = 0.0;            ///< Total mass including merged links [kg].
  /// Pose of the principal inertia frame (origin at the centre of mass) in the link frame.
  Eigen::Isometry3d com_frame = Eigen::Isometry3d::Identity();
  /// Principal moments of inertia [kg m^2].
  Eigen::Vector3d principal_inertia = Eigen::Vector3d::Zero();
  std::vector<CollisionGeometry> collisions;
  std::vector<VisualGeometry> visuals;  ///< Of this link and its fixed-joint descendants.
  /// This link followed by its fixed-joint descendants.
  std::vector<AttachedLink> links;
};

/**
 * Immutable robot description built from a URDF with urdfdom, shared by all envs.
 *
 * Supports a tree of links joined by revolute, continuous and fixed joints with box, cylinder,
 * sphere and mesh collision shapes (meshes become their convex hull); fixed children are merged
 * into their parent body, so a massless root link (base_footprint) fixed to the chassis is the
 * root body's link frame. Visual elements are kept for cameras (VisualGeometry). Every error
 * throws ModelError naming the link or joint.
 */
class RobotModel {
 public:
  /// Parses URDF text (what the robot_description parameter holds); `resolver` turns mesh URIs
  /// other than plain paths and file:// (e.g. package://) into paths, none: such URIs are errors.
  static std::shared_ptr<const RobotModel> fromUrdfString(const std::string& urdf_xml,
                                                          const MeshResolver& resolver = {});
  /// Parses a URDF file; `resolver` as for fromUrdfString().
  static std::shared_ptr<const RobotModel> fromUrdfFile(const std::string& path,
                                                        const MeshResolver& resolver = {});

  const std::string& name() const { return name_; }
  /// Bodies in topological order: the root first, every parent before its children.
  const std::vector<BodyModel>& bodies() const { return bodies_; }
  /// Index of the body driven by the named joint, or -1.
  int bodyOfJoint(const std::string& joint_name) const;
  /// Height of the root link frame above the ground at rest, so that the lowest collision
  /// point touches the ground at zero joint angles [m].
  double restHeight() const { return rest_height_; }
  /// Radius of a vertical cylinder about the root link origin that holds every collision shape
  /// at rest (the robot's footprint, for clearances) [m].
  double footprintRadius() const { return footprint_radius_; }
  /// How far the collision shapes reach ahead of the root link origin at rest, along its x [m].
  double frontReach() const { return front_reach_; }
  /// How far the collision shapes reach to either side of the root link's x axis at rest (the
  /// larger side) [m].
  double halfWidth() const { return half_width_; }
  /// Height of its highest point above the ground at rest, collision and visual shapes alike
  /// (a scanner's housing often has no collision shape; visual meshes, not read here, aside)
  /// [m]: what another robot's sensors see of it.
  double visibleTop() const { return visible_top_; }
  /// The <gazebo> blocks the description holds (ray sensor, diff drive plugin); their link and
  /// joints are checked against the URDF.
  const GazeboBlocks& gazebo() const { return gazebo_; }
  /// The body URDF link `link` belongs to and the link's pose in that body's link frame; false
  /// when the URDF has no such link.
  bool findLink(const std::string& link, int& body, Eigen::Isometry3d& offset) const;

 private:
  RobotModel() = default;
  std::string name_;
  std::vector<BodyModel> bodies_;
  double rest_height_ = 0.0;
  double footprint_radius_ = 0.0;
  double front_reach_ = 0.0;
  double half_width_ = 0.0;
  double visible_top_ = 0.0;
  GazeboBlocks gazebo_;
};

using RobotModelConstPtr = std::shared_ptr<const RobotModel>;

}  // namespace jetbot_rl
