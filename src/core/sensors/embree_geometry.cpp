#include "sensors/embree_geometry.h"

#include "jetbot_rl/errors.h"
#include "world/solid_surfaces.h"

namespace jetbot_rl {

void throwEmbree(RTCDevice device, const std::string& what) {
  const RTCError code = device ? rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN;
  throw ModelError("Embree: " + what + " failed (error " + std::to_string(code) + ")");
}

unsigned attachTriangles(RTCDevice device, RTCScene scene,
                         const std::vector<Eigen::Vector3d>& corners) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (!geometry) throwEmbree(device, "a triangle geometry");
  const std::size_t count = corners.size() / 3;
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), corners.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    throwEmbree(device, "a triangle buffer");
  }
  for (std::size_t i = 0; i < corners.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(corners[i][k]);
    indices[i] = static_cast<unsigned>(i);
  }
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  return id;
}

void appendObstacleSurface(const Obstacle& o, std::vector<Eigen::Vector3d>& corners) {
  const std::vector<Eigen::Vector3d> local = uprightSurface(o, o.height);
  const Eigen::Isometry3d pose = Eigen::Translation3d(o.center.x(), o.center.y(), 0.5 * o.height) *
                                 Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ());
  for (const Eigen::Vector3d& c : local) corners.push_back(pose * c);
}

}  // namespace jetbot_rl
