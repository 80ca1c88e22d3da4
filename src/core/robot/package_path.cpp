#include "jetbot_rl/robot/package_path.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace jetbot_rl {
namespace {

bool isDirectory(const std::string& path) {
  struct stat s {};
  return ::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

std::vector<std::string> subfolders(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != ".." && isDirectory(dir + "/" + name)) out.push_back(name);
    }
    ::closedir(d);
  }
  std::sort(out.begin(), out.end());  // the same choice on every machine
  return out;
}

}  // namespace

std::vector<std::string> searchPath(const char* name) {
  std::vector<std::string> out;
  const char* value = std::getenv(name);
  if (!value) return out;
  std::stringstream s(value);
  for (std::string item; std::getline(s, item, ':');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

std::string findPackageUri(const std::string& uri) {
  static const std::string kScheme = "package://";
  if (uri.compare(0, kScheme.size(), kScheme) != 0) return "";
  const std::string rest = uri.substr(kScheme.size());
  const std::string package = rest.substr(0, rest.find('/'));
  for (const std::string& dir : searchPath("ROS_PACKAGE_PATH")) {
    if (std::ifstream(dir + "/" + package + "/package.xml")) return dir + "/" + rest;
  }
  return "";
}

std::string findGazeboModel(const std::string& uri) {
  static const std::string kScheme = "model://";
  if (uri.rfind(kScheme, 0) != 0) return "";
  // model:///NAME/... (published worlds write it: turtlebot3_house.world) as Gazebo 11 reads it:
  // the slashes before the name count for nothing.
  const std::size_t name_at = uri.find_first_not_of('/', kScheme.size());
  const std::string rest = name_at == std::string::npos ? "" : uri.substr(name_at);
  const std::string name = rest.substr(0, rest.find('/'));
  const std::string tail = rest.substr(name.size());
  if (name.empty()) return "";
  for (const std::string& dir : searchPath("GAZEBO_MODEL_PATH")) {
    if (isDirectory(dir + "/" + name)) return dir + "/" + name + tail;
  }
  for (const std::string& dir : searchPath("ROS_PACKAGE_PATH")) {
    if (isDirectory(dir + "/" + name)) return dir + "/" + name + tail;
    if (isDirectory(dir + "/models/" + name)) return dir + "/models/" + name + tail;
    for (const std::string& package : subfolders(dir)) {
      const std::string models = dir + "/" + package + "/models/" + name;
      if (isDirectory(models)) return models + tail;
    }
  }
  return "";
}

}  // namespace jetbot_rl
