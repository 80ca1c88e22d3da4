#pragma once

#include <string>

namespace jetbot_rl {

/// Why `path` cannot be read as a file, or "" when it is a regular file: "does not exist", "is a
/// directory", "is a FIFO, not a regular file" (opening one would block until a writer comes),
/// ... Every file the core opens (URDF, YAML, map image, mesh, world) is checked first.
std::string fileProblem(const std::string& path);

}  // namespace jetbot_rl
