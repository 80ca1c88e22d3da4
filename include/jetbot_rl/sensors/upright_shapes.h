#pragma once
// People as a camera sees them: upright cylinders and boxes standing on the ground, intersected
// exactly by a packet of rays. Measured faster than an Embree instance each (a second level in
// every env's tree, rebuilt before every image: docs/performance.md), as the scanner's own casts
// are.

#include <Eigen/Core>

namespace jetbot_rl {

struct Obstacle;

/// The rays a camera traces together (a tile of pixels).
constexpr int kPacketLanes = 16;

/// An upright shape standing on the ground (z from 0 to `height`), env frame.
struct UprightShape {
  bool cylinder = true;
  Eigen::Vector2f centre = Eigen::Vector2f::Zero();  ///< [m]
  float cos_yaw = 1.0f, sin_yaw = 0.0f;
  Eigen::Vector2f half = Eigen::Vector2f::Zero();  ///< A box's half extents; (radius, radius) [m]
  float height = 0.0f;                             ///< [m]

  /// `o` as a camera intersects it.
  static UprightShape of(const Obstacle& o);
};

/// A packet's rays: their origins and directions (any length; distances are in its units).
struct PacketRays {
  float org_x[kPacketLanes], org_y[kPacketLanes], org_z[kPacketLanes];
  float dir_x[kPacketLanes], dir_y[kPacketLanes], dir_z[kPacketLanes];
};

/// The nearest hits of a packet's rays on upright shapes.
struct UprightHits {
  float t[kPacketLanes];    ///< In: the farthest distance that counts; out: the nearest hit's.
  int shape[kPacketLanes];  ///< The index of the shape hit, -1: none.
  float normal_x[kPacketLanes], normal_y[kPacketLanes], normal_z[kPacketLanes];  ///< Outward
};

/// Intersects the lanes of `rays` with valid[k] != 0 with `shape` (whose index is `index`),
/// keeping in `hits` each lane's nearest hit beyond distance 0.
void intersectUpright(const UprightShape& shape, int index, const PacketRays& rays,
                      const int* valid, UprightHits& hits);

}  // namespace jetbot_rl
