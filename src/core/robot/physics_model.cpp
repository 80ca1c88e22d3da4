#include "robot/physics_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/urdf_errors.h"

namespace jetbot_rl {
namespace {

btTransform toBullet(const Eigen::Isometry3d& t) {
  const Eigen::Matrix3d& r = t.linear();
  return btTransform(
      btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)),
      btVector3(t.translation().x(), t.translation().y(), t.translation().z()));
}

btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

/// The factories only: LeanDispatcher takes no memory from the configuration's pools.
btDefaultCollisionConstructionInfo tinyPools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 1;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 1;
  return info;
}

}  // namespace

PhysicsModel::PhysicsModel(RobotModelConstPtr robot, const EnvConfig& config)
    : robot_(std::move(robot)),
      ground_(new btStaticPlaneShape(btVector3(0, 0, 1), 0)),
      collision_configuration_(new btDefaultCollisionConfiguration(tinyPools())),
      drive_gain_(config.drive_gain),
      velocity_loop_(config.drive == DriveMode::kVelocityLoop ||
                     (config.drive == DriveMode::kAuto && robot_->gazebo().diff_drive)),
      solver_iterations_(config.solver_iterations) {
  const auto& models = robot_->bodies();
  std::vector<bool> driven(models.size(), false);
  for (const auto& name : config.dof_names) {
    const int body = robot_->bodyOfJoint(name);
    if (body < 0) {
      throw ModelError(jointError(name,
                                  "named in dof_names but not a revolute or continuous joint "
                                  "of the URDF"));
    }
    driven[body] = true;
  }

  std::vector<Eigen::Isometry3d> link_poses;  // link frames in the env frame at rest
  std::vector<int> joint_of_body(models.size(), -1);
  for (size_t i = 0; i < models.size(); ++i) {
    const BodyModel& m = models[i];
    Eigen::Isometry3d rest = Eigen::Isometry3d::Identity();
    rest.translation().z() = robot_->restHeight();
    link_poses.push_back(m.parent < 0 ? rest : link_poses[m.parent] * m.joint_origin);

    Body b;
    b.mass = m.mass;
    b.inertia =
        btVector3(m.principal_inertia.x(), m.principal_inertia.y(), m.principal_inertia.z());
    b.com_in_link = toBullet(m.com_frame);
    b.rest_pose = toBullet(link_poses.back() * m.com_frame);
    b.friction = driven[i] ? kWheelFriction : static_cast<btScalar>(config.caster_friction);
    b.driven = driven[i];
    b.shape = makeShape(m, b.com_in_link);
    if (b.shape->isConvex()) {
      // The support point along -z (world) at rest, margin included.
      const btMatrix3x3& basis = b.rest_pose.getBasis();
      const btVector3 lowest = static_cast<const btConvexShape*>(b.shape)->localGetSupportingVertex(
          basis.transpose() * btVector3(0, 0, -1));
      b.ground_depth = -(basis * lowest).z();
    }
    bodies_.push_back(b);

    if (m.parent >= 0) {
      Joint j;
      j.parent = m.parent;
      j.child = static_cast<int>(i);
      // Child link frame at zero angle, and both COM frames, in the parent's link frame.
      const Eigen::Isometry3d& parent_com = models[m.parent].com_frame;
      const Eigen::Isometry3d child_com = m.joint_origin * m.com_frame;
      const Eigen::Matrix3d parent_to_child = child_com.linear().transpose() * parent_com.linear();
      const Eigen::Quaterniond q(parent_to_child);
      j.rot_parent_to_child = btQuaternion(q.x(), q.y(), q.z(), q.w());
      j.axis_in_child = toBullet(m.com_frame.linear().transpose() * m.axis);
      j.parent_com_to_pivot = toBullet(parent_com.linear().transpose() *
                                       (m.joint_origin.translation() - parent_com.translation()));
      j.pivot_to_child_com = toBullet(m.com_frame.linear().transpose() * m.com_frame.translation());
      j.limited = m.has_position_limits;
      j.lower = m.lower;
      j.upper = m.upper;
      joint_of_body[i] = static_cast<int>(joints_.size());
      joints_.push_back(j);
    }
  }

  scales_wheels_ = config.randomization.wheel_radius_scale != std::vector<double>{1.0, 1.0};
  for (std::size_t i = 0; scales_wheels_ && i < bodies_.size(); ++i) {
    if (bodies_[i].driven && !bodies_[i].shape->isConvex()) {
      throw ModelError("link '" + models[i].link_name +
                       "': wheel_radius_scale needs a wheel of one collision element (a "
                       "cylinder, sphere or mesh), got " +
                       std::to_string(models[i].collisions.size()));
    }
  }

  for (const auto& name : config.dof_names) {
    const BodyModel& m = models[robot_->bodyOfJoint(name)];
    Dof d;
    d.name = name;
    d.joint = joint_of_body[robot_->bodyOfJoint(name)];
    d.urdf_velocity_limit = m.velocity_limit;
    d.urdf_effort_limit = m.effort_limit;
    // A positive parameter wins over the URDF, for every dof.
    d.velocity_source =
        config.wheel_velocity_limit > 0.0 ? LimitSource::kParameter : LimitSource::kUrdf;
    d.velocity_limit =
        config.wheel_velocity_limit > 0.0 ? config.wheel_velocity_limit : m.velocity_limit;
    // The effort: the parameter, else the Gazebo diff drive plugin's wheel torque for its
    // wheels (what Gazebo applies), else the URDF's.
    const auto& plugin = robot_->gazebo().diff_drive;
    const bool plugin_wheel = plugin && plugin->wheel_torque > 0.0 &&
                              (name == plugin->left_joint || name == plugin->right_joint);
    d.effort_source = config.effort_limit > 0.0 ? LimitSource::kParameter
                      : plugin_wheel            ? LimitSource::kGazebo
                                                : LimitSource::kUrdf;
    d.effort_limit = config.effort_limit > 0.0 ? config.effort_limit
                     : plugin_wheel            ? plugin->wheel_torque
                                               : m.effort_limit;
    if (!(std::isfinite(d.velocity_limit) && d.velocity_limit > 0.0)) {
      std::ostringstream s;
      s << "needs <limit velocity> > 0 [rad/s] to clamp targets, got " << d.velocity_limit
        << "; set the wheel_velocity_limit parameter [rad/s]";
      throw ModelError(jointError(name, s.str()));
    }
    if (!(std::isfinite(d.effort_limit) && d.effort_limit > 0.0)) {
      std::ostringstream s;
      s << "needs <limit effort> > 0 [N m] for its drive, got " << d.effort_limit
        << "; set the effort_limit parameter [N m]";
      throw ModelError(jointError(name, s.str()));
    }
    dofs_.push_back(d);
  }
}

PhysicsModel::~PhysicsModel() = default;

namespace {

/// Round shapes roll: their contact point moves on every step, so a point from an earlier step is
/// useless as soon as the surface lifts off; a small breaking threshold drops it at once instead
/// of solving for it on every iteration.
template <class Shape>
class RollingShape : public Shape {
 public:
  using Shape::Shape;
  btScalar getContactBreakingThreshold(btScalar) const override {
    return PhysicsModel::kRollingContactBreakingThreshold;
  }
};

/// btUniformScalingShape's margin is its child's, scaled: a rounded tread stays rounded.
using RollingScaledShape = RollingShape<btUniformScalingShape>;

bool isRound(const CollisionGeometry& g) {
  return g.type == CollisionGeometry::Type::kCylinder || g.type == CollisionGeometry::Type::kSphere;
}

/// The convex hull of a mesh's vertices, expressed in the frame `in_frame` maps them to.
std::unique_ptr<btCollisionShape> makeHull(const CollisionGeometry& g,
                                           const btTransform& in_frame) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const auto& v : g.vertices) hull->addPoint(in_frame * toBullet(v), false);
  hull->recalcLocalAabb();
  hull->setMargin(0);  // the hull is the mesh's surface; the ground is its only contact
  return hull;
}

/// A cylinder along the COM frame's axis `axis` (0, 1, 2), with a rounded tread.
std::unique_ptr<btCollisionShape> makeCylinder(double radius, double length, int axis) {
  std::unique_ptr<btCollisionShape> cylinder;
  const btScalar r = radius, h = length / 2;
  switch (axis) {
    case 0:
      cylinder = std::make_unique<RollingShape<btCylinderShapeX>>(btVector3(h, r, r));
      break;
    case 1:
      cylinder = std::make_unique<RollingShape<btCylinderShape>>(btVector3(r, h, r));
      break;
    default:
      cylinder = std::make_unique<RollingShape<btCylinderShapeZ>>(btVector3(r, r, h));
  }
  // A flat tread touches the ground at one of its edges (Bullet's support point), which makes
  // left and right wheels roll differently; a fully rounded tread of the same outer size touches
  // in its middle plane, like a real tyre.
  cylinder->setMargin(std::min(radius, length / 2) * PhysicsModel::kTreadRounding);
  return cylinder;
}

std::unique_ptr<btCollisionShape> makePrimitive(const CollisionGeometry& g) {
  switch (g.type) {
    case CollisionGeometry::Type::kBox: {
      auto box =
          std::make_unique<btBoxShape>(btVector3(g.size.x() / 2, g.size.y() / 2, g.size.z() / 2));
      box->setMargin(PhysicsModel::kCollisionMargin);
      return box;
    }
    case CollisionGeometry::Type::kCylinder:
      return makeCylinder(g.size.x(), g.size.y(), 2);
    case CollisionGeometry::Type::kSphere:
    case CollisionGeometry::Type::kMesh:  // made by makeHull()
      break;
  }
  return std::make_unique<RollingShape<btSphereShape>>(g.size.x());
}

/// The axis (0, 1, 2) of the frame that `direction` lies along, or -1.
int alignedAxis(const btVector3& direction) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::abs(direction[k]) - 1.0) < 1e-6) return k;
  }
  return -1;
}

}  // namespace

btCollisionShape* PhysicsModel::makeShape(const BodyModel& body, const btTransform& com_in_link) {
  auto keep = [this](std::unique_ptr<btCollisionShape> shape) {
    shapes_.push_back(std::move(shape));
    return shapes_.back().get();
  };
  if (body.collisions.empty()) return keep(std::make_unique<btEmptyShape>());
  const btTransform link_in_com = com_in_link.inverse();

  // A lone sphere or cylinder centred on the COM (a wheel) needs no compound around it.
  if (body.collisions.size() == 1 && isRound(body.collisions[0])) {
    const CollisionGeometry& g = body.collisions[0];
    const btTransform in_com = link_in_com * toBullet(g.origin);
    if (in_com.getOrigin().length() < 1e-9) {
      if (g.type == CollisionGeometry::Type::kSphere) return keep(makePrimitive(g));
      const int axis = alignedAxis(in_com.getBasis().getColumn(2));
      if (axis >= 0) return keep(makeCylinder(g.size.x(), g.size.y(), axis));
    }
  }

  // Hull vertices can be placed in the COM frame directly: a lone mesh needs no compound.
  if (body.collisions.size() == 1 && body.collisions[0].type == CollisionGeometry::Type::kMesh) {
    return keep(makeHull(body.collisions[0], link_in_com * toBullet(body.collisions[0].origin)));
  }

  const bool all_round = std::all_of(body.collisions.begin(), body.collisions.end(), isRound);
  std::unique_ptr<btCompoundShape> compound =
      all_round ? std::make_unique<RollingShape<btCompoundShape>>(false)
                : std::make_unique<btCompoundShape>(/*enableDynamicAabbTree=*/false);
  for (const auto& g : body.collisions) {
    const btTransform in_com = link_in_com * toBullet(g.origin);
    std::unique_ptr<btCollisionShape> primitive = g.type == CollisionGeometry::Type::kMesh
                                                      ? makeHull(g, btTransform::getIdentity())
                                                      : makePrimitive(g);
    compound->addChildShape(in_com, primitive.get());
    shapes_.push_back(std::move(primitive));
  }
  return keep(std::move(compound));
}

std::unique_ptr<btCollisionShape> PhysicsModel::makeScaledShape(int body, btScalar scale) const {
  auto* convex = static_cast<btConvexShape*>(bodies_.at(body).shape);
  const int type = convex->getShapeType();
  if (type == CYLINDER_SHAPE_PROXYTYPE || type == SPHERE_SHAPE_PROXYTYPE) {
    return std::make_unique<RollingScaledShape>(convex, scale);
  }
  return std::make_unique<btUniformScalingShape>(convex, scale);
}

}  // namespace jetbot_rl
