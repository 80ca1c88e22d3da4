#pragma once
// A Gazebo world's <visual> elements as a camera draws them: triangles in the world frame with
// their material's diffuse colour (loadGazeboWorld() reads them when asked to).
#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <optional>
#include <sdf/sdf.hh>
#include <string>
#include <vector>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "world/gazebo/ogre_materials.h"

namespace jetbot_rl {

/// The diffuse colour of a Gazebo material script (Gazebo/Grey, Gazebo/Wood, ...), or false for
/// one it does not know.
bool gazeboScriptColour(const std::string& script, Eigen::Vector3f& colour);

/// What a visual's <material> says of its colour: its <diffuse> where given, else the name of
/// its Gazebo script (Gazebo/Grey, ...); neither: grey.
struct VisualMaterial {
  std::optional<Eigen::Vector3f> diffuse;  ///< RGB as given (clamped to [0, 1] when drawn).
  std::string script;
  std::vector<std::string> script_uris;  ///< Its script's <uri>s: folders or files of scripts.
  /// Its `<pbr>`'s albedo map as given (metal workflow, else specular), or "".
  std::string albedo_map;
  std::string file_path;  ///< The SDF file it was read from, when sdformat knows it.
};

/// The material of an sdformat visual.
VisualMaterial materialOf(const sdf::Visual& visual);

/// What readVisual() reads with and into: the world's file, the mesh resolver, the visuals and
/// notes it appends to, and the textures read so far (one image per file; nullptr: not readable,
/// noted once).
struct VisualSink {
  std::string world_path;
  MeshResolver resolver;
  std::vector<WorldVisual>* out = nullptr;
  std::vector<std::string>* notes = nullptr;
  std::map<std::string, std::shared_ptr<const TextureImage>> textures;
  std::size_t texture_bytes = 0;  ///< Their decoded bytes (at most kMaxTextureBytes).
  ScriptMaterials scripts;        ///< The material scripts read so far.
};

/// Appends a visual of geometry `g` and `material` (named `name`, at `pose` in the world;
/// `where`: its file and line) to `sink`: its surface (sdfSurface()) and colour; a plane is the
/// ground (left out), a material script it does not know is noted (drawn grey). A mesh without a
/// `<material>` shows its file's own materials, as Gazebo draws it: one visual per material, its
/// diffuse colour or texture (a texture that cannot be read is noted, its colour drawn).
/// ConfigError naming the file, line and visual for a size or pose beyond the bounds or a mesh
/// that cannot be read.
void readVisual(const sdf::Geometry& g, const VisualMaterial& material,
                const Eigen::Isometry3d& pose, const std::string& name, const std::string& where,
                VisualSink& sink);

}  // namespace jetbot_rl
