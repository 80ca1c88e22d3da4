// A Gazebo world file before sdformat reads it (sdf_prepass.h).
#include "world/gazebo/sdf_prepass.h"

#include <tinyxml2.h>

#include <filesystem>
#include <map>
#include <set>
#include <system_error>
#include <vector>

#include "jetbot_rl/config/file_checks.h"
#include "world/gazebo/inertia_free_models.h"
#include "world/gazebo/plain_models.h"
#include "world/gazebo/sdf_names.h"

namespace jetbot_rl {
namespace {

/// The element printed without its name (attribute or <name>) and its own <pose>: what two
/// repeats share.
std::string shapeKey(const tinyxml2::XMLElement& e) {
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* copy = e.DeepClone(&doc)->ToElement();
  copy->DeleteAttribute("name");
  for (const char* tag : {"name", "pose"}) {
    while (tinyxml2::XMLElement* c = copy->FirstChildElement(tag)) copy->DeleteChild(c);
  }
  tinyxml2::XMLPrinter printer(nullptr, /*compact=*/true);
  copy->Accept(&printer);
  return printer.CStr();
}

/// True when the state poses a link of model `name`.
bool linkInState(const SavedState& state, const std::string& name) {
  const auto it = state.links.lower_bound(name + "::");
  return it != state.links.end() && it->first.rfind(name + "::", 0) == 0;
}

bool hasPlacementFrame(const tinyxml2::XMLElement& e) {
  return e.Attribute("placement_frame") || e.FirstChildElement("placement_frame");
}

/// The SDF file a model folder stands for: its model.config's first <sdf>, else model.sdf.
std::string modelFile(const std::filesystem::path& folder) {
  tinyxml2::XMLDocument config;
  const std::filesystem::path config_path = folder / "model.config";
  if (fileProblem(config_path.string()).empty() &&
      config.LoadFile(config_path.c_str()) == tinyxml2::XML_SUCCESS) {
    const tinyxml2::XMLElement* model = config.FirstChildElement("model");
    const tinyxml2::XMLElement* sdf = model ? model->FirstChildElement("sdf") : nullptr;
    if (sdf && sdf->GetText()) return (folder / sdf->GetText()).string();
  }
  return (folder / "model.sdf").string();
}

std::string includeUri(const tinyxml2::XMLElement& include) {
  const tinyxml2::XMLElement* uri = include.FirstChildElement("uri");
  return uri && uri->GetText() ? uri->GetText() : "";
}

/// The SDF file an <include> names (relative to `folder`, absolute, or through `find`), as
/// sdformat follows it; "" when not found.
std::string includedFile(const tinyxml2::XMLElement& include, const std::filesystem::path& folder,
                         const IncludeFinder& find) {
  const std::string text = includeUri(include);
  std::string found;
  if (!text.empty() && text.find("://") == std::string::npos && text[0] != '/') {
    found = (folder / text).lexically_normal().string();
  } else if (!text.empty()) {
    found = text[0] == '/' ? text : find(text);
  }
  if (found.empty()) return "";
  return std::filesystem::is_directory(found) ? modelFile(found) : found;
}

/// What an included file brings into the world: a model (and its name), or not (a light:
/// Gazebo's model://sun). A file that cannot be read counts as a model (sdformat says why).
struct Included {
  bool model = true;
  std::string name;
};

/// The include's Included, each file read once (`known`: file -> what it holds).
const Included& included(const tinyxml2::XMLElement& include, const std::filesystem::path& folder,
                         const IncludeFinder& find, std::map<std::string, Included>& known) {
  const std::string file = includedFile(include, folder, find);
  const auto [it, is_new] = known.emplace(file, Included());
  tinyxml2::XMLDocument doc;
  if (is_new && !file.empty() && fileProblem(file).empty() &&
      doc.LoadFile(file.c_str()) == tinyxml2::XML_SUCCESS) {
    const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
    const tinyxml2::XMLElement* first = sdf ? sdf->FirstChildElement() : nullptr;
    it->second.model = !first || std::string(first->Name()) == "model";
    it->second.name = it->second.model ? nameAttribute(first) : "";
  }
  return it->second;
}

class IncludeWalk {
 public:
  explicit IncludeWalk(const IncludeFinder& find) : find_(find) {}

  /// "" when every include under `file` ends, else the problem.
  std::string walk(const std::string& file) {
    std::error_code error;
    const std::string key = std::filesystem::weakly_canonical(file, error).string();
    for (std::size_t k = 0; k < chain_.size(); ++k) {
      if (chain_[k] != key) continue;
      std::string text = "its includes come back to " + file + ": ";
      for (std::size_t j = k; j < chain_.size(); ++j) text += chain_[j] + " includes ";
      return text + file + " (a model cannot include itself)";
    }
    if (done_.count(key)) return "";
    if (static_cast<int>(chain_.size()) >= kMaxIncludeDepth) {
      return file + ": included " + std::to_string(chain_.size()) + " levels deep, more than " +
             std::to_string(kMaxIncludeDepth);
    }
    if (++files_ > kMaxIncludedFiles) {
      return "more than " + std::to_string(kMaxIncludedFiles) + " included files";
    }
    if (const std::string problem = fileProblem(file); !problem.empty()) {
      return file + ": " + problem;
    }
    tinyxml2::XMLDocument doc;
    if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS) return "";  // sdformat says why
    chain_.push_back(key);
    const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
    std::string problem = visit(doc.RootElement(), file, folder);
    chain_.pop_back();
    if (problem.empty()) done_.insert(key);
    return problem;
  }

 private:
  std::string visit(const tinyxml2::XMLElement* e, const std::string& file,
                    const std::filesystem::path& folder) {
    for (; e; e = e->NextSiblingElement()) {
      if (std::string(e->Name()) == "include") {
        const std::string target = includedFile(*e, folder, find_);
        if (target.empty()) continue;  // sdformat names what it cannot find
        const std::string problem = walk(target);
        if (!problem.empty()) {
          return file + ":" + std::to_string(e->GetLineNum()) + ": <include> of " + includeUri(*e) +
                 ": " + problem;
        }
        continue;
      }
      const std::string problem = visit(e->FirstChildElement(), file, folder);
      if (!problem.empty()) return problem;
    }
    return "";
  }

  const IncludeFinder& find_;
  std::vector<std::string> chain_;  // the files being walked, outermost first (canonical)
  std::set<std::string> done_;      // files whose includes all end
  int files_ = 0;
};

}  // namespace

std::string includeProblem(const std::string& path, const IncludeFinder& find) {
  return IncludeWalk(find).walk(path);
}

PrepassedWorld prepassWorld(const std::string& path, bool visuals, const IncludeFinder& find,
                            std::vector<std::string>* refused_inertias, SavedState* state) {
  PrepassedWorld out;
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) return out;
  tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  tinyxml2::XMLElement* world = sdf ? sdf->FirstChildElement("world") : nullptr;
  if (!world) return out;
  if (refused_inertias) stripInertials(*world, path, *refused_inertias);
  bool state_changed = false;
  if (state) *state = takeSavedState(*world, path, state_changed);
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  // A name given twice (an include's own, else its model's) is left to sdformat, which refuses
  // it.
  std::map<std::string, Included> included_files;
  std::map<std::string, int> names;
  for (const tinyxml2::XMLElement* e = world->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const bool include = std::string(e->Name()) == "include";
    std::string name = include ? entityName(*e) : nameAttribute(e);
    if (include && name.empty()) name = included(*e, folder, find, included_files).name;
    ++names[name];
  }
  std::map<std::string, std::string> first;  // shape key -> the first model's name
  std::size_t sdformat_models = 0;           // models left to sdformat so far
  for (tinyxml2::XMLElement* e = world->FirstChildElement(); e;) {
    tinyxml2::XMLElement* next = e->NextSiblingElement();
    const std::string tag = e->Name();
    const bool include = tag == "include";
    if (include) {  // the prepassed text is read from a string: no folder of its own
      tinyxml2::XMLElement* uri = e->FirstChildElement("uri");
      const std::string text = includeUri(*e);
      if (!text.empty() && text.find("://") == std::string::npos && text[0] != '/') {
        uri->SetText((folder / text).lexically_normal().c_str());
      }
    }
    const std::string name = entityName(*e);
    ignition::math::Pose3d pose;
    // Read by sdformat as it is: not a model, a name sdformat would question, a placement frame,
    // a pose of the saved state's or one that is more than six numbers, an include that does
    // not say where (its model's own pose then counts).
    if ((tag != "model" && !include) || !ordinaryName(name) || names[name] > 1 ||
        hasPlacementFrame(*e) ||
        (state && (state->models.count(name) || linkInState(*state, name))) ||
        !readPlainPose(*e, pose) || (include && !e->FirstChildElement("pose"))) {
      if (tag == "model" || (include && included(*e, folder, find, included_files).model)) {
        ++sdformat_models;
      }
      e = next;
      continue;
    }
    const auto [it, is_first] = first.emplace(shapeKey(*e), name);
    PlainModel plain;
    if (!is_first) {
      out.repeats.push_back({name, it->second, pose});
    } else if (!include && readPlainModel(*e, path, visuals, plain)) {
      plain.place = sdformat_models;
      out.plain.push_back(std::move(plain));
    } else {
      if (!include || included(*e, folder, find, included_files).model) ++sdformat_models;
      e = next;
      continue;
    }
    world->DeleteChild(e);
    e = next;
  }
  if (out.repeats.empty() && out.plain.empty() && !refused_inertias && !state_changed) return out;
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  out.text = printer.CStr();
  return out;
}

std::string sdfFileProblem(const std::string& path, const std::string& newest) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    if (doc.ErrorID() == tinyxml2::XML_ERROR_FILE_NOT_FOUND ||
        doc.ErrorID() == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED) {
      return path + ": cannot be read";
    }
    return path + ":" + std::to_string(doc.ErrorLineNum()) + ": not XML: " + doc.ErrorStr();
  }
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  if (!sdf) {
    const tinyxml2::XMLElement* root = doc.RootElement();
    return path + ": not an SDF file (its root element is <" +
           (root ? std::string(root->Name()) : std::string()) + ">, not <sdf>)";
  }
  const char* version = sdf->Attribute("version");
  const auto number = [](const std::string& v) {
    const auto dot = v.find('.');
    try {
      return dot == std::string::npos
                 ? -1.0
                 : std::stoi(v.substr(0, dot)) * 1000.0 + std::stoi(v.substr(dot + 1));
    } catch (const std::exception&) {
      return -1.0;
    }
  };
  const double v = version ? number(version) : -1.0;
  if (v < 1000.0 || v > number(newest)) {
    return path + ":" + std::to_string(sdf->GetLineNum()) + ": <sdf version=\"" +
           (version ? version : "") + "\"> is not a version sdformat reads (1.0 to " + newest + ")";
  }
  return "";
}

}  // namespace jetbot_rl
