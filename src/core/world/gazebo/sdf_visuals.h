#pragma once
// A Gazebo world's <visual> elements as a camera draws them: triangles in the world frame with
// their material's diffuse colour (loadGazeboWorld() reads them when asked to).
#include <Eigen/Geometry>
#include <optional>
#include <sdf/sdf.hh>
#include <string>
#include <vector>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {

/// The diffuse colour of a Gazebo material script (Gazebo/Grey, Gazebo/Wood, ...), or false for
/// one it does not know.
bool gazeboScriptColour(const std::string& script, Eigen::Vector3f& colour);

/// What a visual's <material> says of its colour: its <diffuse> where given, else the name of
/// its Gazebo script (Gazebo/Grey, ...); neither: grey.
struct VisualMaterial {
  std::optional<Eigen::Vector3f> diffuse;  ///< RGB as given (clamped to [0, 1] when drawn).
  std::string script;
};

/// The material of an sdformat visual.
VisualMaterial materialOf(const sdf::Visual& visual);

/// Appends a visual of geometry `g` and `material` (named `name`, at `pose` in the world;
/// `where`: its file and line) to `out`: its surface (sdfSurface()) and colour; a plane is the
/// ground (left out), a material script it does not know is noted in `notes` (drawn grey).
/// ConfigError naming the file, line and visual for a size or pose beyond the bounds or a mesh
/// that cannot be read.
void readVisual(const sdf::Geometry& g, const VisualMaterial& material,
                const Eigen::Isometry3d& pose, const std::string& name, const std::string& where,
                const std::string& world_path, const MeshResolver& resolver,
                std::vector<WorldVisual>& out, std::vector<std::string>& notes);

}  // namespace jetbot_rl
