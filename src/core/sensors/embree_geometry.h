#pragma once
// What the camera's Embree scenes share: errors named as ours, triangles attached to a scene,
// obstacles as triangles.
#include <embree3/rtcore.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace jetbot_rl {

struct Obstacle;

/// ModelError "Embree: `what` failed (error N)" with the device's last error.
[[noreturn]] void throwEmbree(RTCDevice device, const std::string& what);

/// Triangles (three corners each) as one Embree triangle geometry of `scene`; its geometry id.
unsigned attachTriangles(RTCDevice device, RTCScene scene,
                         const std::vector<Eigen::Vector3d>& corners);

/// Appends the surface of upright obstacle `o` (standing on the ground) in the env frame.
void appendObstacleSurface(const Obstacle& o, std::vector<Eigen::Vector3d>& corners);

}  // namespace jetbot_rl
