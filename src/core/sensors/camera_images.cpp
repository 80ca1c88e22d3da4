// What a camera's images are and how its scene looks, apart from rendering them.
#include "jetbot_rl/sensors/camera_scene.h"

namespace jetbot_rl {

CameraImageView CameraImages::resize(int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  rgb.resize(3 * pixels);
  depth.resize(pixels);
  label.resize(pixels);
  return {rgb.data(), depth.data(), label.data()};
}

const Eigen::Vector3f& Appearance::colour(SurfaceClass c) const {
  switch (c) {
    case SurfaceClass::kGround:
      return ground;
    case SurfaceClass::kWall:
      return wall;
    case SurfaceClass::kMap:
      return map;
    case SurfaceClass::kObstacle:
      return obstacle;
    case SurfaceClass::kMover:
    case SurfaceClass::kRobot:  // robots have their URDF colours (render())
      return mover;
    case SurfaceClass::kNone:
      break;
  }
  return sky;
}

Eigen::Isometry3d opticalFrame(const Eigen::Isometry3d& body) {
  // Optical z is body x, optical x is body -y, optical y is body -z.
  Eigen::Matrix3d optical_in_body;
  optical_in_body << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d out = body;
  out.linear() = body.linear() * optical_in_body;
  return out;
}

}  // namespace jetbot_rl
