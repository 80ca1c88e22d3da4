#include "jetbot_rl/robot/diff_drive.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/robot/urdf_errors.h"

namespace jetbot_rl {
namespace {

/// Wheel axes must lie across the robot within this: cos(8 degrees) of root y.
constexpr double kMinAxisAlongY = 0.99;
/// A cylinder counts as a tyre when its axis is this close to the joint axis (cosine).
constexpr double kCoaxial = 0.999;
/// The two derived radii may differ by this fraction before wheel_radius must be given.
constexpr double kRadiusMismatch = 0.01;

/// Link frame of every body in the root link frame at zero joint angles.
std::vector<Eigen::Isometry3d> restPoses(const RobotModel& robot) {
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& body : robot.bodies()) {
    poses.push_back(body.parent < 0 ? Eigen::Isometry3d::Identity()
                                    : poses[body.parent] * body.joint_origin);
  }
  return poses;
}

/// Distance of `p` from the line through the origin along unit `axis`.
double fromAxis(const Eigen::Vector3d& p, const Eigen::Vector3d& axis) {
  return (p - p.dot(axis) * axis).norm();
}

/// Largest radius about the joint axis of the body's round collisions (cylinders along the
/// axis, spheres, meshes), or -1 when it has none.
double rollingRadius(const BodyModel& body) {
  double radius = -1.0;
  for (const auto& g : body.collisions) {
    const Eigen::Vector3d centre = g.origin.translation();
    switch (g.type) {
      case CollisionGeometry::Type::kSphere:
        radius = std::max(radius, fromAxis(centre, body.axis) + g.size.x());
        break;
      case CollisionGeometry::Type::kCylinder:
        if (std::abs(g.origin.linear().col(2).dot(body.axis)) >= kCoaxial) {
          radius = std::max(radius, fromAxis(centre, body.axis) + g.size.x());
        }
        break;
      case CollisionGeometry::Type::kMesh:
        for (const auto& v : g.vertices)
          radius = std::max(radius, fromAxis(g.origin * v, body.axis));
        break;
      case CollisionGeometry::Type::kBox:
        break;
    }
  }
  return radius;
}

}  // namespace

DiffDrive::DiffDrive(double wheel_radius, double wheel_separation, DriveWheel left,
                     DriveWheel right)
    : radius_(wheel_radius),
      separation_(wheel_separation),
      left_(std::move(left)),
      right_(std::move(right)) {
  if (!positiveFinite(radius_)) throwInvalid("wheel_radius", radius_, "must be positive");
  if (!positiveFinite(separation_)) {
    throwInvalid("wheel_separation", separation_, "must be positive");
  }
  for (const DriveWheel* w : {&left_, &right_}) {
    if (!positiveFinite(w->velocity_limit)) {
      throwInvalid("wheel_velocity_limit", w->velocity_limit,
                   "must be positive for joint '" + w->joint + "'");
    }
    if (std::abs(w->direction) != 1.0) {
      throwInvalid("direction", w->direction, "must be +1 or -1 for joint '" + w->joint + "'");
    }
  }
  if (left_.dof + right_.dof != 1 || left_.dof * right_.dof != 0) {
    throwInvalid("dof", std::to_string(left_.dof) + ", " + std::to_string(right_.dof),
                 "the two wheels must be dofs 0 and 1");
  }
}

DiffDrive DiffDrive::fromRobot(const RobotModel& robot, const std::vector<std::string>& dof_names,
                               const std::vector<double>& velocity_limits, double wheel_radius,
                               double wheel_separation) {
  if (dof_names.size() != 2 || velocity_limits.size() != 2) {
    std::ostringstream names;
    for (std::size_t i = 0; i < dof_names.size(); ++i) names << (i ? ", " : "[") << dof_names[i];
    names << "]";
    throwInvalid("dof_names", names.str(), "a differential drive needs exactly two wheel joints");
  }
  if (!std::isfinite(wheel_radius) || wheel_radius < 0.0) {
    throwInvalid("wheel_radius", wheel_radius, "must be >= 0 m (0: derived from the URDF)");
  }
  if (!std::isfinite(wheel_separation) || wheel_separation < 0.0) {
    throwInvalid("wheel_separation", wheel_separation, "must be >= 0 m (0: derived from the URDF)");
  }
  // The Gazebo diff drive plugin's wheels give the defaults of its own joints.
  std::string radius_source = "parameter", separation_source = "parameter";
  if (const auto& plugin = robot.gazebo().diff_drive;
      plugin && dof_names[0] == plugin->left_joint && dof_names[1] == plugin->right_joint) {
    if (wheel_radius == 0.0 && plugin->wheel_diameter > 0.0) {
      wheel_radius = 0.5 * plugin->wheel_diameter;
      radius_source = "Gazebo diff drive plugin's wheelDiameter";
    }
    if (wheel_separation == 0.0 && plugin->wheel_separation > 0.0) {
      wheel_separation = plugin->wheel_separation;
      separation_source = "Gazebo diff drive plugin's wheelSeparation";
    }
  }
  const std::vector<Eigen::Isometry3d> poses = restPoses(robot);
  struct Found {
    const BodyModel* body;
    Eigen::Vector3d position;  // joint origin in the root frame at rest
    Eigen::Vector3d axis;      // in the root frame
    DriveWheel wheel;
  };
  std::vector<Found> found;
  for (int d = 0; d < 2; ++d) {
    const std::string& name = dof_names[d];
    const int b = robot.bodyOfJoint(name);
    if (b < 0) {
      throw ModelError(jointError(name,
                                  "named in dof_names but not a revolute or continuous "
                                  "joint of the URDF"));
    }
    const BodyModel& body = robot.bodies()[b];
    const Eigen::Vector3d axis = poses[b].linear() * body.axis;
    if (std::abs(axis.y()) < kMinAxisAlongY) {
      std::ostringstream s;
      s << "axis (" << axis.transpose()
        << ") in the root frame does not point across the robot (along y); a differential "
           "drive needs wheel axes along y";
      throw ModelError(jointError(name, s.str()));
    }
    DriveWheel wheel;
    wheel.joint = name;
    wheel.dof = d;
    // Rolling on the ground below the axle, turning about +y moves the wheel forward (+x).
    wheel.direction = axis.y() > 0.0 ? 1.0 : -1.0;
    wheel.velocity_limit = velocity_limits[d];
    found.push_back({&body, poses[b].translation(), axis, wheel});
  }
  if (std::abs(found[0].position.y() - found[1].position.y()) < 1e-6) {
    throw ModelError("joints '" + dof_names[0] + "' and '" + dof_names[1] +
                     "' are at the same y in the root frame: cannot tell the left wheel from "
                     "the right");
  }
  if (found[1].position.y() > found[0].position.y()) std::swap(found[0], found[1]);
  const Found& l = found[0];
  const Found& r = found[1];

  if (wheel_radius == 0.0) {
    double radii[2];
    for (int i = 0; i < 2; ++i) {
      radii[i] = rollingRadius(*found[i].body);
      if (radii[i] <= 0.0) {
        throw ModelError(jointError(
            found[i].wheel.joint,
            "link '" + found[i].body->link_name +
                "' has no round collision (a cylinder along the joint axis, a sphere or a mesh) "
                "to derive the wheel radius from; set the wheel_radius parameter [m]"));
      }
    }
    if (std::abs(radii[0] - radii[1]) > kRadiusMismatch * std::max(radii[0], radii[1])) {
      std::ostringstream s;
      s << "wheel radius " << radii[0] << " m differs from " << radii[1] << " m of joint '"
        << r.wheel.joint << "'; set the wheel_radius parameter [m]";
      throw ModelError(jointError(l.wheel.joint, s.str()));
    }
    wheel_radius = 0.5 * (radii[0] + radii[1]);
    radius_source =
        "URDF: collisions of links '" + l.body->link_name + "', '" + r.body->link_name + "'";
  }
  if (wheel_separation == 0.0) {
    wheel_separation = std::abs((l.position - r.position).dot(l.axis.normalized()));
    if (!positiveFinite(wheel_separation) || wheel_separation < 1e-6) {
      throw ModelError("joints '" + l.wheel.joint + "' and '" + r.wheel.joint +
                       "' are not apart along their axis; set the wheel_separation parameter [m]");
    }
    separation_source =
        "URDF: joints '" + l.wheel.joint + "', '" + r.wheel.joint + "' along their axis";
  }
  DiffDrive drive(wheel_radius, wheel_separation, l.wheel, r.wheel);
  drive.radius_source_ = radius_source;
  drive.separation_source_ = separation_source;
  return drive;
}

DiffDrive DiffDrive::fromEnv(const BatchedEnv& env) {
  std::vector<double> limits;
  for (const auto& dof : env.dofLimits()) limits.push_back(dof.velocity_limit);
  return fromRobot(env.robot(), env.config().dof_names, limits, env.config().wheel_radius,
                   env.config().wheel_separation);
}

std::array<double, 2> DiffDrive::wheelTargets(const PlanarTwist& twist) const {
  if (!std::isfinite(twist.linear) || !std::isfinite(twist.angular)) {
    std::ostringstream s;
    s << "twist (linear " << twist.linear << " m/s, angular " << twist.angular
      << " rad/s) is not finite";
    throw InputError(s.str());
  }
  // Ground speed of each wheel's contact, then the joint velocity that rolls it there.
  const double half = 0.5 * separation_ * twist.angular;
  std::array<double, 2> targets;
  targets[left_.dof] = left_.direction * (twist.linear - half) / radius_;
  targets[right_.dof] = right_.direction * (twist.linear + half) / radius_;
  double scale = 1.0;
  for (const DriveWheel* w : {&left_, &right_}) {
    const double speed = std::abs(targets[w->dof]);
    if (speed > w->velocity_limit) scale = std::min(scale, w->velocity_limit / speed);
  }
  targets[0] *= scale;
  targets[1] *= scale;
  return targets;
}

PlanarTwist DiffDrive::bodyTwist(const std::array<double, 2>& dof_velocities) const {
  const double left = left_.direction * dof_velocities[left_.dof] * radius_;
  const double right = right_.direction * dof_velocities[right_.dof] * radius_;
  return {0.5 * (left + right), (right - left) / separation_};
}

std::string DiffDrive::describe() const {
  std::ostringstream s;
  const auto sign = [](double d) { return d > 0 ? "+" : "-"; };
  s << "wheel_radius " << radius_ << " m (" << radius_source_ << "), wheel_separation "
    << separation_ << " m (" << separation_source_ << "), left wheel '" << left_.joint << "' (dof "
    << left_.dof << ", forward " << sign(left_.direction) << ", limit " << left_.velocity_limit
    << " rad/s), right wheel '" << right_.joint << "' (dof " << right_.dof << ", forward "
    << sign(right_.direction) << ", limit " << right_.velocity_limit << " rad/s)";
  return s.str();
}

}  // namespace jetbot_rl
