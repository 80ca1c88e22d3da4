#pragma once
// Gazebo 11's material scripts (Ogre's `.material` files, which a visual's <script> names with
// the folders that hold them): what a camera draws of a material, its diffuse colour and first
// texture.
#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace jetbot_rl {

/// A material of a script: its first pass's `diffuse` and its first `texture_unit`'s `texture`
/// and `scale` (a parent's, `material A : B`, where it gives none).
struct ScriptMaterial {
  std::optional<Eigen::Vector3f> diffuse;  ///< RGB as given.
  std::string texture;                     ///< The file name as given; "" without one.
  Eigen::Vector2f scale{1.0f, 1.0f};       ///< Ogre's texture scale: coordinates divided by it.
};

/// The material scripts of some folders, each `.material` file read once (at most
/// kMaxScriptBytes each, kMaxScriptFiles a folder, kMaxScriptTotalBytes in all).
class ScriptMaterials {
 public:
  static constexpr long kMaxScriptBytes = 1 << 20;
  static constexpr int kMaxScriptFiles = 1000;
  static constexpr long kMaxScriptTotalBytes = 64 << 20;

  /// Material `name` as the script files in `folders` (folders or files, as a <script>'s <uri>s
  /// resolve) define it, or none. `problems`: files it could not read, each once.
  std::optional<ScriptMaterial> find(const std::string& name,
                                     const std::vector<std::string>& folders,
                                     std::vector<std::string>& problems);

 private:
  /// The materials a file (or a folder's files) defines, read at its first use.
  const std::map<std::string, ScriptMaterial>& read(const std::string& folder,
                                                    std::vector<std::string>& problems);

  std::map<std::string, std::map<std::string, ScriptMaterial>> by_folder_;
  long read_bytes_ = 0;  // of every script read
};

/// The materials Ogre script text `text` defines (`material NAME [: PARENT] { ... }`), added to
/// `out` (a parent is looked up in `out` as read so far). Text it does not follow is skipped.
void parseMaterialScript(const std::string& text, std::map<std::string, ScriptMaterial>& out);

}  // namespace jetbot_rl
