#pragma once

// The surfaces of a Gazebo world's shapes as triangles, three corners each, in their own frame
// [m], and what makes a WorldSolid of a shape (solid_surfaces.cpp). Round surfaces have their
// facets outside the true surface: a cut holds the true cross-section.

#include <Eigen/Geometry>
#include <vector>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {

/// An axis this close to z counts as upright (cos of about 0.01 degrees).
constexpr double kUprightCos = 1.0 - 1e-8;

/// A box of `size` centred on the origin.
std::vector<Eigen::Vector3d> boxSurface(const Eigen::Vector3d& size);
/// A cylinder along z of `radius` and `length`, centred on the origin.
std::vector<Eigen::Vector3d> cylinderSurface(double radius, double length);
/// An ellipsoid of semi-axes `radii` centred on `centre`.
std::vector<Eigen::Vector3d> ellipsoidSurface(
    const Eigen::Vector3d& radii, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());
/// The side walls of a `<polyline>`: its points extruded from z = 0 to `height`.
std::vector<Eigen::Vector3d> polylineSurface(const std::vector<Eigen::Vector2d>& points,
                                             double height);

/// The surface of upright `o` (a box or a vertical cylinder) `length` tall, centred on its own
/// origin.
std::vector<Eigen::Vector3d> uprightSurface(const Obstacle& o, double length);

/// Makes `solid` the upright `o` from `bottom` to `top` [m], with its bounds.
void setUpright(WorldSolid& solid, Obstacle o, double bottom, double top);
/// Makes `solid` the surface `local` (triangle corners) placed by `pose`, with its extent.
void setSurface(WorldSolid& solid, const std::vector<Eigen::Vector3d>& local,
                const Eigen::Isometry3d& pose);
/// `solid` moved by `move` (in the world frame): an upright one stays exact while `move` keeps
/// its axis vertical, else it becomes its surface.
WorldSolid moved(const WorldSolid& solid, const Eigen::Isometry3d& move);

}  // namespace jetbot_rl
