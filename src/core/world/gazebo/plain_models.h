#pragma once

// Plain models: the world-level models that scripts write by the thousand (links of boxes,
// cylinders and spheres at plain poses), read from the XML without sdformat. sdformat 12 copies a
// model's whole description for every <model> it reads (about 13 ms and 2.5 MB each), so a world
// of 20,000 distinct boxes would take minutes and tens of GB. Anything else in a model (frames,
// relative_to, includes, nested models, meshes, plugins, materials, any attribute or element not
// listed here) leaves it to sdformat, which reads it as before.

#include <tinyxml2.h>

#include <ignition/math/Pose3.hh>
#include <sdf/Geometry.hh>
#include <string>
#include <vector>

#include "world/gazebo/sdf_visuals.h"

namespace jetbot_rl {

/// A <collision> or <visual> of a plain link.
struct PlainShape {
  std::string name;
  int line = 0;                 ///< Its line in the world file.
  ignition::math::Pose3d pose;  ///< In its link's frame.
  sdf::Geometry geometry;       ///< A box, cylinder or sphere.
  VisualMaterial material;      ///< A visual's colour (its <diffuse> or Gazebo script).
};

/// A <link> of a plain model.
struct PlainLink {
  std::string name;
  ignition::math::Pose3d pose;  ///< In its model's frame.
  std::vector<PlainShape> collisions, visuals;
};

/// A world-level <model> read without sdformat.
struct PlainModel {
  std::string name;
  ignition::math::Pose3d pose;  ///< In the world.
  std::vector<PlainLink> links;
  /// Its links' inertias that sdformat refuses, named as stripInertials() names them.
  std::vector<std::string> warnings;
  /// How many of the models sdformat reads come before it in the file (its place among them).
  std::size_t place = 0;
};

/// The pose in `parent`'s <pose> as sdformat reads it (ignition's Pose3d of x y z roll pitch
/// yaw), identity without one; false when it has an attribute (relative_to, degrees,
/// rotation_format; an empty frame or relative_to is the default frame), more than one, or text
/// other than six finite numbers: sdformat's to read.
bool readPlainPose(const tinyxml2::XMLElement& parent, ignition::math::Pose3d& pose);

/// `model` (a world's <model>, from file `file`) as a plain model; false, leaving it to sdformat,
/// when it is anything more (see above). `visuals`: its <visual>s too, whose <material> may hold
/// colours (ambient, diffuse, specular, emissive: 3 or 4 numbers in [0, 1]) and a Gazebo
/// <script> (its <uri>s and <name>); without, they are checked and passed over. A link's <inertial>
/// is judged as sdformat judges it and removed from `model` (refused ones in PlainModel::warnings,
/// as Gazebo 11 reads them: without).
bool readPlainModel(tinyxml2::XMLElement& model, const std::string& file, bool visuals,
                    PlainModel& out);

/// A name sdformat takes without a word: not empty, no "::", not reserved ("__...__", "world").
bool ordinaryName(const std::string& name);

}  // namespace jetbot_rl
