#pragma once

#include <string>

namespace jetbot_rl {

/// "joint 'NAME': WHAT": an error about a URDF joint, naming it.
inline std::string jointError(const std::string& joint, const std::string& what) {
  return "joint '" + joint + "': " + what;
}

/// "link 'NAME': WHAT": an error about a URDF link, naming it.
inline std::string linkError(const std::string& link, const std::string& what) {
  return "link '" + link + "': " + what;
}

}  // namespace jetbot_rl
