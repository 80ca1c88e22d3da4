#pragma once

// Model folders as sdformat should read them where it refuses a link's inertia that Gazebo 11
// loads (issue 48: published worlds with a zero or repeated moment of inertia).

#include <tinyxml2.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace jetbot_rl {

/// Removes every <inertial> under `e` (nothing here reads a link's mass or inertia), and appends
/// "FILE:LINE: model 'M', link 'L': ..." to `refused` for each that sdformat refuses (ignition's
/// MassMatrix3 rule, with SDF's defaults), `file` being the file `e` was read from.
void stripInertials(tinyxml2::XMLElement& e, const std::string& file,
                    std::vector<std::string>& refused);

/**
 * Copies of model folders without <inertial> elements, in a temporary folder that goes with the
 * object: each folder's .sdf files rewritten, everything else in it linked (meshes and files
 * named relative to them stay where they are found).
 */
class InertiaFreeModels {
 public:
  InertiaFreeModels();
  ~InertiaFreeModels();
  InertiaFreeModels(const InertiaFreeModels&) = delete;
  InertiaFreeModels& operator=(const InertiaFreeModels&) = delete;

  /// What stands for `found` (a model folder or an SDF file, as a find callback found it): its
  /// copy, made at the first call; `found` itself when it is neither or cannot be copied.
  std::string copyOf(const std::string& found);
  /// The inertias the copies left out that sdformat refuses (stripInertials()).
  const std::vector<std::string>& refused() const { return refused_; }

 private:
  std::vector<std::string> refused_;
  std::filesystem::path root_;
  std::map<std::string, std::string> copies_;  // folder -> its copy
};

}  // namespace jetbot_rl
