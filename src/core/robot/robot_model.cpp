#include "jetbot_rl/robot/robot_model.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>

#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/robot/urdf_errors.h"
#include "robot/robot_visuals.h"
#include "robot/urdf_pose.h"

namespace jetbot_rl {
namespace {

/// urdfdom reports parse errors through console_bridge only: collect them for our exception.
class CapturingOutputHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages_ << text << "; ";
  }
  std::string text() const { return messages_.str(); }

 private:
  std::ostringstream messages_;
};

urdf::ModelInterfaceSharedPtr parseCapturingErrors(const std::string& xml, std::string& errors) {
  static std::mutex console_mutex;  // console_bridge's handler is process-wide
  std::lock_guard<std::mutex> lock(console_mutex);
  CapturingOutputHandler handler;
  console_bridge::OutputHandler* previous = console_bridge::getOutputHandler();
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    errors = e.what();
  }
  console_bridge::useOutputHandler(previous);
  errors += handler.text();
  return model;
}

/// Inertial of one URDF link, validated, expressed in the body's link frame.
struct MassElement {
  double mass;
  Eigen::Vector3d com;
  Eigen::Matrix3d inertia;  // about the com, in the body's link frame
};

MassElement massElement(const urdf::Link& link, const Eigen::Isometry3d& offset) {
  const urdf::Inertial& in = *link.inertial;
  if (!positiveFinite(in.mass)) {
    std::ostringstream s;
    s << "mass must be positive and finite, got " << in.mass;
    throw ModelError(linkError(link.name, s.str()));
  }
  Eigen::Matrix3d inertia;
  inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  if (!inertia.allFinite())
    throw ModelError(linkError(link.name, "inertia has a non-finite entry"));
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();
  const double tolerance = 1e-9 * moments.cwiseAbs().maxCoeff();
  const bool triangle = moments(0) + moments(1) >= moments(2) - tolerance &&
                        moments(0) + moments(2) >= moments(1) - tolerance &&
                        moments(1) + moments(2) >= moments(0) - tolerance;
  if (moments.minCoeff() <= 0.0 || !triangle) {
    std::ostringstream s;
    s << "invalid inertia (principal moments " << moments.transpose()
      << " kg m^2 must be positive and satisfy the triangle inequality)";
    throw ModelError(linkError(link.name, s.str()));
  }
  const Eigen::Isometry3d frame = offset * toIsometry(in.origin);
  return {in.mass, frame.translation(), frame.linear() * inertia * frame.linear().transpose()};
}

/// The convex hull of a mesh collision, scaled; errors name the link and the URI or path.
void loadMesh(const urdf::Link& link, const urdf::Mesh& mesh, const MeshResolver& resolver,
              CollisionGeometry& g) {
  g.type = CollisionGeometry::Type::kMesh;
  g.mesh_uri = mesh.filename;
  g.size << mesh.scale.x, mesh.scale.y, mesh.scale.z;
  if (!g.size.allFinite() || (g.size.array() == 0.0).any()) {
    std::ostringstream s;
    s << "mesh '" << mesh.filename << "': scale must be finite and non-zero, got "
      << g.size.transpose();
    throw ModelError(linkError(link.name, s.str()));
  }
  std::string path;
  try {
    path = resolveMeshUri(mesh.filename, resolver);
  } catch (const ModelError& e) {
    throw ModelError(linkError(link.name, e.what()));
  }
  try {
    g.vertices = loadMeshHull(path);
  } catch (const ModelError& e) {
    const std::string from =
        path == mesh.filename ? "" : " (resolved from '" + mesh.filename + "')";
    throw ModelError(linkError(link.name, e.what() + from));
  }
  for (auto& v : g.vertices) v = v.cwiseProduct(g.size);
}

CollisionGeometry collisionGeometry(const urdf::Link& link, const urdf::Collision& collision,
                                    const Eigen::Isometry3d& offset, const MeshResolver& resolver) {
  CollisionGeometry g;
  g.origin = offset * toIsometry(collision.origin);
  if (!collision.geometry) throw ModelError(linkError(link.name, "collision without geometry"));
  if (!setPrimitive(*collision.geometry, g)) {
    if (collision.geometry->type != urdf::Geometry::MESH) {
      throw ModelError(linkError(link.name, "unsupported collision geometry type"));
    }
    loadMesh(link, static_cast<const urdf::Mesh&>(*collision.geometry), resolver, g);
    return g;
  }
  const int used = g.type == CollisionGeometry::Type::kBox        ? 3
                   : g.type == CollisionGeometry::Type::kCylinder ? 2
                                                                  : 1;
  for (int i = 0; i < used; ++i) {
    if (!positiveFinite(g.size(i))) {
      throw ModelError(linkError(link.name, "collision shape dimensions must be positive"));
    }
  }
  return g;
}

/// Lowest (`sign` -1) or highest (+1) point of a primitive along axis `axis` (0 x, 1 y, 2 z) of
/// the frame it is expressed in [m]; a mesh without vertices (a visual's, read only for cameras):
/// -inf for the highest.
double extremeAlong(const CollisionGeometry& g, const Eigen::Isometry3d& body_pose, int axis,
                    double sign) {
  const Eigen::Isometry3d pose = body_pose * g.origin;
  const Eigen::Matrix3d& r = pose.linear();
  const double centre = pose.translation()(axis);
  switch (g.type) {
    case CollisionGeometry::Type::kBox:
      return centre + sign * 0.5 *
                          (std::abs(r(axis, 0)) * g.size(0) + std::abs(r(axis, 1)) * g.size(1) +
                           std::abs(r(axis, 2)) * g.size(2));
    case CollisionGeometry::Type::kCylinder: {
      const double along = std::abs(r(axis, 2));  // the cylinder's own axis is its z
      return centre + sign * (0.5 * g.size(1) * along +
                              g.size(0) * std::sqrt(std::max(0.0, 1.0 - along * along)));
    }
    case CollisionGeometry::Type::kSphere:
      return centre + sign * g.size(0);
    case CollisionGeometry::Type::kMesh: {
      double extreme = -sign * std::numeric_limits<double>::infinity();
      for (const auto& v : g.vertices)
        extreme = sign * std::max(sign * extreme, sign * (pose * v)(axis));
      return extreme;
    }
  }
  return centre;
}

double extremeZ(const CollisionGeometry& g, const Eigen::Isometry3d& body_pose, double sign) {
  return extremeAlong(g, body_pose, 2, sign);
}

double lowestZ(const CollisionGeometry& g, const Eigen::Isometry3d& body_pose) {
  return extremeZ(g, body_pose, -1.0);
}

class BodyBuilder {
 public:
  BodyBuilder(std::vector<BodyModel>& bodies, const MeshResolver& resolver)
      : bodies_(bodies), resolver_(resolver) {}

  /// Adds the body rooted at `link` and, recursively, all bodies below it.
  void addBody(const urdf::Link& link, int parent, const urdf::Joint* joint,
               const Eigen::Isometry3d& joint_origin) {
    BodyModel body;
    body.link_name = link.name;
    body.parent = parent;
    body.joint_origin = joint_origin;
    if (joint) setJoint(*joint, body);
    std::vector<MassElement> masses;
    std::vector<std::pair<const urdf::Link*, const urdf::Joint*>> moving_children;
    collect(link, Eigen::Isometry3d::Identity(), body, masses, moving_children);
    setMass(masses, body);
    const int index = static_cast<int>(bodies_.size());
    bodies_.push_back(body);
    for (const auto& child : moving_children) {
      const Eigen::Isometry3d offset = offsetOf(child.second->parent_link_name, bodies_[index]);
      addBody(*child.first, index, child.second,
              offset * toIsometry(child.second->parent_to_joint_origin_transform));
    }
  }

 private:
  static Eigen::Isometry3d offsetOf(const std::string& link, const BodyModel& body) {
    for (const auto& attached : body.links) {
      if (attached.name == link) return attached.offset;
    }
    return Eigen::Isometry3d::Identity();
  }

  static void setJoint(const urdf::Joint& joint, BodyModel& body) {
    body.joint_name = joint.name;
    body.has_position_limits = joint.type == urdf::Joint::REVOLUTE;
    Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!axis.allFinite() || axis.norm() < 1e-9) {
      throw ModelError("joint '" + joint.name + "': axis must be a non-zero vector");
    }
    body.axis = axis.normalized();
    if (joint.limits) {
      body.lower = joint.limits->lower;
      body.upper = joint.limits->upper;
      body.velocity_limit = joint.limits->velocity;
      body.effort_limit = joint.limits->effort;
      if (body.has_position_limits && !(body.lower <= body.upper)) {
        throw ModelError("joint '" + joint.name + "': lower limit exceeds upper limit");
      }
    }
  }

  /// Merges `link` and its fixed-joint descendants into `body`.
  void collect(const urdf::Link& link, const Eigen::Isometry3d& offset, BodyModel& body,
               std::vector<MassElement>& masses,
               std::vector<std::pair<const urdf::Link*, const urdf::Joint*>>& moving_children) {
    const auto parent = link.getParent();
    body.links.push_back({link.name, offset, parent ? parent->name : std::string()});
    if (link.inertial) masses.push_back(massElement(link, offset));
    for (const auto& collision : link.collision_array) {
      if (collision)
        body.collisions.push_back(collisionGeometry(link, *collision, offset, resolver_));
    }
    for (const auto& visual : link.visual_array) {
      if (visual) body.visuals.push_back(visualGeometry(link, *visual, offset, resolver_));
    }
    for (const auto& child : link.child_links) {
      const urdf::Joint& joint = *child->parent_joint;
      switch (joint.type) {
        case urdf::Joint::FIXED:
          collect(*child, offset * toIsometry(joint.parent_to_joint_origin_transform), body, masses,
                  moving_children);
          break;
        case urdf::Joint::REVOLUTE:
        case urdf::Joint::CONTINUOUS:
          moving_children.emplace_back(child.get(), &joint);
          break;
        default:
          throw ModelError("joint '" + joint.name +
                           "': unsupported type; only revolute, continuous and fixed joints are "
                           "supported");
      }
    }
  }

  static void setMass(const std::vector<MassElement>& masses, BodyModel& body) {
    if (masses.empty()) {
      throw ModelError(linkError(body.link_name,
                                 "moving link has no <inertial> (nor has any link fixed to it)"));
    }
    double mass = 0.0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    for (const auto& m : masses) {
      mass += m.mass;
      com += m.mass * m.com;
    }
    com /= mass;
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (const auto& m : masses) {  // parallel-axis theorem
      const Eigen::Vector3d d = m.com - com;
      inertia +=
          m.inertia + m.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
    Eigen::Matrix3d axes = eigen.eigenvectors();
    if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
    body.mass = mass;
    body.principal_inertia = eigen.eigenvalues();
    body.com_frame = Eigen::Isometry3d::Identity();
    body.com_frame.translation() = com;
    body.com_frame.linear() = axes;
  }

  std::vector<BodyModel>& bodies_;
  const MeshResolver& resolver_;
};

/// Farthest horizontal distance from the root link origin that geometry `g` (posed by
/// `body_pose` in the root link frame) can reach: its centre's plus its bounding radius [m].
double horizontalReach(const CollisionGeometry& g, const Eigen::Isometry3d& body_pose) {
  const Eigen::Isometry3d pose = body_pose * g.origin;
  double radius = 0.0;
  switch (g.type) {
    case CollisionGeometry::Type::kBox:
      radius = 0.5 * g.size.norm();
      break;
    case CollisionGeometry::Type::kCylinder:
      radius = std::hypot(g.size.x(), 0.5 * g.size.y());
      break;
    case CollisionGeometry::Type::kSphere:
      radius = g.size.x();
      break;
    case CollisionGeometry::Type::kMesh:
      for (const auto& v : g.vertices) radius = std::max(radius, v.norm());
      break;
  }
  return pose.translation().head<2>().norm() + radius;
}

}  // namespace

std::shared_ptr<const RobotModel> RobotModel::fromUrdfString(const std::string& urdf_xml,
                                                             const MeshResolver& resolver) {
  std::string errors;
  const urdf::ModelInterfaceSharedPtr urdf = parseCapturingErrors(urdf_xml, errors);
  if (!urdf)
    throw ModelError("URDF could not be parsed: " + (errors.empty() ? "unknown error" : errors));
  const urdf::LinkConstSharedPtr root = urdf->getRoot();
  if (!root) throw ModelError("URDF has no root link");

  std::shared_ptr<RobotModel> model(new RobotModel());
  model->name_ = urdf->getName();
  BodyBuilder(model->bodies_, resolver).addBody(*root, -1, nullptr, Eigen::Isometry3d::Identity());

  // Pose of every body's link frame in the root link frame at zero joint angles.
  std::vector<Eigen::Isometry3d> poses;
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& body : model->bodies_) {
    poses.push_back(body.parent < 0 ? Eigen::Isometry3d::Identity()
                                    : poses[body.parent] * body.joint_origin);
    for (const auto& g : body.collisions) lowest = std::min(lowest, lowestZ(g, poses.back()));
  }
  if (!std::isfinite(lowest)) throw ModelError("URDF has no collision shapes to stand on");
  model->rest_height_ = -lowest;
  double top = lowest;
  for (std::size_t b = 0; b < model->bodies_.size(); ++b) {
    for (const auto& g : model->bodies_[b].collisions) {
      model->footprint_radius_ = std::max(model->footprint_radius_, horizontalReach(g, poses[b]));
      model->front_reach_ = std::max(model->front_reach_, extremeAlong(g, poses[b], 0, 1.0));
      model->half_width_ = std::max({model->half_width_, extremeAlong(g, poses[b], 1, 1.0),
                                     -extremeAlong(g, poses[b], 1, -1.0)});
      top = std::max(top, extremeZ(g, poses[b], 1.0));
    }
    for (const auto& v : model->bodies_[b].visuals)
      top = std::max(top, extremeZ(v.shape, poses[b], 1.0));
  }
  model->visible_top_ = top - lowest;
  model->gazebo_ = parseGazeboBlocks(urdf_xml);
  int body = 0;
  Eigen::Isometry3d offset;
  if (const auto& ray = model->gazebo_.ray; ray && !model->findLink(ray->link, body, offset)) {
    throw ModelError("ray sensor '" + ray->name + "': link '" + ray->link + "' is not in the URDF");
  }
  if (const auto& drive = model->gazebo_.diff_drive) {
    for (const std::string& joint : {drive->left_joint, drive->right_joint}) {
      if (!joint.empty() && model->bodyOfJoint(joint) < 0) {
        throw ModelError("diff drive plugin: joint '" + joint +
                         "' is not a moving joint of the URDF");
      }
    }
  }
  return model;
}

bool RobotModel::findLink(const std::string& link, int& body, Eigen::Isometry3d& offset) const {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    for (const auto& l : bodies_[b].links) {
      if (l.name == link) {
        body = static_cast<int>(b);
        offset = l.offset;
        return true;
      }
    }
  }
  return false;
}

std::shared_ptr<const RobotModel> RobotModel::fromUrdfFile(const std::string& path,
                                                           const MeshResolver& resolver) {
  if (const std::string problem = fileProblem(path); !problem.empty()) {
    throw ModelError("cannot read URDF file '" + path + "': it " + problem);
  }
  std::ifstream file(path);
  if (!file) throw ModelError("cannot read URDF file '" + path + "'");
  std::ostringstream text;
  text << file.rdbuf();
  return fromUrdfString(text.str(), resolver);
}

int RobotModel::bodyOfJoint(const std::string& joint_name) const {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].parent >= 0 && bodies_[i].joint_name == joint_name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace jetbot_rl
