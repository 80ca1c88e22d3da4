#pragma once
// What a camera may see of an env's bodies and people, cheaply: bounding spheres, and the angle
// each spans from the camera, tested against the cone of a tile's rays (camera_model.h) before any
// ray of the tile is traced against what they bound.

#include <Eigen/Geometry>
#include <vector>

#include "jetbot_rl/sensors/camera_model.h"

namespace jetbot_rl {

struct Obstacle;

/// The bounding sphere of upright `o` (standing on the ground): centre and radius [m].
Eigen::Vector4d uprightBoundingSphere(const Obstacle& o);

/// Spheres that together bound upright `o`, appended to `out` (centres and radii [m]): a tall
/// one (a person) in a stack of up to four, each about as high as it is wide, far tighter than
/// one sphere about it all.
void appendBoundingSpheres(const Obstacle& o, std::vector<Eigen::Vector4f>& out);

/// A bounding sphere as the camera sees it: the direction to its centre and the sine and cosine
/// of the angle it spans about it.
struct SeenSphere {
  Eigen::Vector3f towards;  ///< unit, optical frame
  float sin_span, cos_span;
  int owner;  ///< what it bounds (its index), or -1
  /// Whether any ray of `cone` may meet the sphere: the angle between the centre and the axis
  /// is at most the cone's half-angle plus the sphere's.
  bool meets(const TileCone& cone) const {
    return cone.everything ||
           towards.dot(cone.axis) >= cone.cos_half * cos_span - cone.sin_half * sin_span;
  }
};

/// `spheres` (env frame; `owners`: what each bounds, or nullptr) as seen from `pose` (the
/// optical frame in the env frame) into `out`, leaving out those behind the camera or beyond
/// `far` [m]; a sphere holding the camera spans every direction.
void seenSpheres(const std::vector<Eigen::Vector4f>& spheres, const std::vector<int>* owners,
                 const Eigen::Isometry3d& pose, float far, std::vector<SeenSphere>& out);

}  // namespace jetbot_rl
