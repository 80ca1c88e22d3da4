#include "jetbot_rl/config/file_checks.h"

#include <filesystem>
#include <system_error>

namespace jetbot_rl {

std::string fileProblem(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows links: their target counts
  switch (status.type()) {
    case fs::file_type::regular:
      return "";
    case fs::file_type::not_found:
      return "does not exist";
    case fs::file_type::directory:
      return "is a directory, not a file";
    case fs::file_type::fifo:
      return "is a FIFO, not a regular file (reading it would wait for a writer)";
    case fs::file_type::socket:
      return "is a socket, not a regular file";
    case fs::file_type::block:
    case fs::file_type::character:
      return "is a device, not a regular file";
    default:
      return error ? "cannot be examined: " + error.message() : "is not a regular file";
  }
}

}  // namespace jetbot_rl
