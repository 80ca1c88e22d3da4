#include "world/gazebo/inertia_free_models.h"

#include <cstdlib>
#include <ignition/math/MassMatrix3.hh>
#include <system_error>

#include "world/gazebo/sdf_names.h"

namespace jetbot_rl {
namespace {

/// The number in `parent`'s first <tag>, else `fallback` (SDF's default).
double inertiaNumber(const tinyxml2::XMLElement* parent, const char* tag, double fallback) {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(tag) : nullptr;
  double value = fallback;
  return e && e->QueryDoubleText(&value) == tinyxml2::XML_SUCCESS ? value : fallback;
}

}  // namespace

void stripInertials(tinyxml2::XMLElement& e, const std::string& file,
                    std::vector<std::string>& refused) {
  while (tinyxml2::XMLElement* inertial = e.FirstChildElement("inertial")) {
    // As sdformat's Link::Load judges it: the mass matrix of <mass> and <inertia> (defaults 1 and
    // the unit moments).
    const tinyxml2::XMLElement* i = inertial->FirstChildElement("inertia");
    const ignition::math::MassMatrix3d matrix(
        inertiaNumber(inertial, "mass", 1.0),
        {inertiaNumber(i, "ixx", 1.0), inertiaNumber(i, "iyy", 1.0), inertiaNumber(i, "izz", 1.0)},
        {inertiaNumber(i, "ixy", 0.0), inertiaNumber(i, "ixz", 0.0), inertiaNumber(i, "iyz", 0.0)});
    if (!matrix.IsValid()) {
      const tinyxml2::XMLElement* model = e.Parent() ? e.Parent()->ToElement() : nullptr;
      refused.push_back(file + ":" + std::to_string(inertial->GetLineNum()) + ": model '" +
                        nameAttribute(model) + "', link '" + nameAttribute(&e) +
                        "': an inertia sdformat refuses (moments " +
                        std::to_string(matrix.DiagonalMoments().X()) + ", " +
                        std::to_string(matrix.DiagonalMoments().Y()) + ", " +
                        std::to_string(matrix.DiagonalMoments().Z()) +
                        "): read without it, as Gazebo 11 reads it (collision shapes need none)");
    }
    e.DeleteChild(inertial);
  }
  for (tinyxml2::XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
    stripInertials(*c, file, refused);
  }
}

InertiaFreeModels::InertiaFreeModels() {
  std::string pattern = (std::filesystem::temp_directory_path() / "jetbot_rl_models_XXXXXX");
  if (::mkdtemp(pattern.data())) root_ = pattern;
}

InertiaFreeModels::~InertiaFreeModels() {
  std::error_code error;
  if (!root_.empty()) std::filesystem::remove_all(root_, error);
}

std::string InertiaFreeModels::copyOf(const std::string& found) {
  namespace fs = std::filesystem;
  std::error_code error;
  const bool folder = fs::is_directory(found, error);
  if (root_.empty() || (!folder && !fs::is_regular_file(found, error))) return found;
  const fs::path source = folder ? fs::path(found) : fs::path(found).parent_path();
  auto [it, is_new] = copies_.emplace(source.string(), std::string());
  if (is_new) {
    const fs::path copy = root_ / std::to_string(copies_.size()) / source.filename();
    fs::create_directories(copy, error);
    for (const fs::directory_entry& entry : fs::directory_iterator(source, error)) {
      const fs::path target = copy / entry.path().filename();
      tinyxml2::XMLDocument doc;
      if (entry.path().extension() == ".sdf" && entry.is_regular_file(error) &&
          doc.LoadFile(entry.path().c_str()) == tinyxml2::XML_SUCCESS && doc.RootElement()) {
        stripInertials(*doc.RootElement(), entry.path().string(), refused_);
        if (doc.SaveFile(target.c_str()) == tinyxml2::XML_SUCCESS) continue;
      }
      fs::create_symlink(fs::absolute(entry.path()), target, error);
    }
    it->second = copy.string();
  }
  return folder ? it->second : (fs::path(it->second) / fs::path(found).filename()).string();
}

}  // namespace jetbot_rl
