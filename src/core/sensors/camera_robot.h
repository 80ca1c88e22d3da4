#pragma once
// A robot as cameras see it: per body, one Embree scene of its URDF visuals (boxes, cylinders,
// spheres and meshes as triangles) in the body's link frame, with each geometry's colour; every
// env scene instances the bodies of its robots at their poses (the model/data split again).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "jetbot_rl/robot/robot_model.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace jetbot_rl {

/// The triangles (three corners each) of visual `v` in its body's link frame [m]; ModelError
/// naming the link for a mesh that cannot be resolved or read.
std::vector<Eigen::Vector3d> visualTriangles(const VisualGeometry& v);

class CameraRobot {
 public:
  /// The visuals of every body of `robot` on `device`; `hidden_link`'s (the camera's own link,
  /// its housing, which its rays start inside) are left out of the robot's own view. ModelError
  /// naming the link for a visual mesh that cannot be read.
  CameraRobot(RTCDeviceTy* device, const RobotModel& robot, const std::string& hidden_link);
  ~CameraRobot();
  CameraRobot(const CameraRobot&) = delete;
  CameraRobot& operator=(const CameraRobot&) = delete;

  int numBodies() const { return static_cast<int>(bodies_.size()); }
  /// Body `b` as the robot's own camera (`own`) or another robot's sees it; nullptr: nothing.
  RTCSceneTy* body(int b, bool own) const { return own ? bodies_[b].own : bodies_[b].all; }
  /// A sphere holding all of that scene: its centre in the body's link frame [m] and radius [m].
  const Eigen::Vector4d& boundingSphere(int b, bool own) const {
    return own ? bodies_[b].own_sphere : bodies_[b].sphere;
  }
  /// The colour of geometry `geometry` of that scene.
  const Eigen::Vector3f& colour(int b, bool own, unsigned geometry) const {
    return (own ? bodies_[b].own_colours : bodies_[b].colours).at(geometry);
  }

 private:
  struct Body {
    RTCSceneTy* all = nullptr;
    RTCSceneTy* own = nullptr;  // == all when the hidden link is not among its visuals
    std::vector<Eigen::Vector3f> colours, own_colours;  // per geometry id
    Eigen::Vector4d sphere = Eigen::Vector4d::Zero(), own_sphere = Eigen::Vector4d::Zero();
  };
  void release();

  std::vector<Body> bodies_;
};

}  // namespace jetbot_rl
