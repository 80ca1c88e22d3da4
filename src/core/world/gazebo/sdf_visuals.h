#pragma once
// A Gazebo world's <visual> elements as a camera draws them: triangles in the world frame with
// their material's diffuse colour (loadGazeboWorld() reads them when asked to).
#include <Eigen/Geometry>
#include <sdf/sdf.hh>
#include <string>
#include <vector>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {

/// The diffuse colour of a Gazebo material script (Gazebo/Grey, Gazebo/Wood, ...), or false for
/// one it does not know.
bool gazeboScriptColour(const std::string& script, Eigen::Vector3f& colour);

/// Appends `visual` (named `name`, at `pose` in the world; `where`: its file and line) to `out`:
/// its surface (sdfSurface()) and colour; a plane is the ground (left out), a material script it
/// does not know is noted in `notes` (drawn grey). ConfigError naming the file, line and visual
/// for a size or pose beyond the bounds or a mesh that cannot be read.
void readVisual(const sdf::Visual& visual, const Eigen::Isometry3d& pose, const std::string& name,
                const std::string& where, const std::string& world_path,
                const MeshResolver& resolver, std::vector<WorldVisual>& out,
                std::vector<std::string>& notes);

}  // namespace jetbot_rl
