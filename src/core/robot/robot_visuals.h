#pragma once

#include <urdf_model/link.h>

#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

/// Sets `g`'s type and size from a URDF box, cylinder or sphere (full extents; radius, length;
/// radius [m]); false for another geometry (a mesh), `g` unchanged.
bool setPrimitive(const urdf::Geometry& geometry, CollisionGeometry& g);

/// The visual `visual` of `link`, whose frame is `offset` in its body's link frame: its shape, its
/// material's colour and, for a mesh, the resolved file (a mesh that cannot be resolved is kept
/// with the reason, refused only by a camera that draws it). ModelError naming the link for a
/// size that is negative or not finite, or a visual without geometry.
VisualGeometry visualGeometry(const urdf::Link& link, const urdf::Visual& visual,
                              const Eigen::Isometry3d& offset, const MeshResolver& resolver);

}  // namespace jetbot_rl
