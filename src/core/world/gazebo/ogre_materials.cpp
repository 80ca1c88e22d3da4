#include "world/gazebo/ogre_materials.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "jetbot_rl/config/file_checks.h"

namespace jetbot_rl {

namespace {

/// The words of a script line, its `//` comment left out and braces as words of their own.
std::vector<std::string> words(std::string line) {
  if (const auto comment = line.find("//"); comment != std::string::npos) line.resize(comment);
  std::string spaced;
  for (char c : line) {
    if (c == '{' || c == '}') {
      spaced += ' ';
      spaced += c;
      spaced += ' ';
    } else {
      spaced += c;
    }
  }
  std::istringstream in(spaced);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// Numbers `w[1..n]` as floats, or false.
bool numbers(const std::vector<std::string>& w, std::size_t n, float* out) {
  if (w.size() < n + 1) return false;
  for (std::size_t i = 0; i < n; ++i) {
    try {
      std::size_t used = 0;
      out[i] = std::stof(w[i + 1], &used);
      if (used != w[i + 1].size()) return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return true;
}

}  // namespace

void parseMaterialScript(const std::string& text, std::map<std::string, ScriptMaterial>& out) {
  std::istringstream lines(text);
  std::vector<std::string> blocks;  // the open blocks' keywords, outermost first
  std::string pending;              // a statement whose block may open on the next line
  ScriptMaterial* material = nullptr;
  bool diffuse_seen = false, texture_seen = false, in_first_unit = false;
  for (std::string line; std::getline(lines, line);) {
    const std::vector<std::string> w = words(line);
    std::size_t i = 0;
    while (i < w.size()) {
      if (w[i] == "{") {
        blocks.push_back(pending);
        if (pending == "texture_unit" && material) in_first_unit = !texture_seen;
        pending.clear();
        ++i;
        continue;
      }
      if (w[i] == "}") {
        if (!blocks.empty()) {
          if (blocks.back() == "texture_unit") in_first_unit = false;
          blocks.pop_back();
        }
        if (blocks.empty()) material = nullptr;
        pending.clear();
        ++i;
        continue;
      }
      // A statement: its words up to a brace.
      std::vector<std::string> s;
      while (i < w.size() && w[i] != "{" && w[i] != "}") s.push_back(w[i++]);
      pending = s.front();
      if (blocks.empty() && s.front() == "material" && s.size() >= 2) {
        std::string name = s[1], parent;
        if (const auto colon = name.find(':'); colon != std::string::npos) {  // A:B
          parent = name.substr(colon + 1);
          name.resize(colon);
        }
        if (s.size() >= 4 && s[2] == ":") parent = s[3];
        if (s.size() >= 3 && s[2].size() > 1 && s[2][0] == ':') parent = s[2].substr(1);
        ScriptMaterial start;
        if (const auto p = out.find(parent); !parent.empty() && p != out.end()) start = p->second;
        material = &(out[name] = start);
        diffuse_seen = false;
        texture_seen = false;
        continue;
      }
      if (!material) continue;
      const bool in_pass = std::find(blocks.begin(), blocks.end(), "pass") != blocks.end();
      float v[3];
      if (s.front() == "diffuse" && in_pass && !diffuse_seen && numbers(s, 3, v)) {
        material->diffuse = Eigen::Vector3f(v[0], v[1], v[2]);
        diffuse_seen = true;
      } else if (s.front() == "texture" && in_first_unit && s.size() >= 2) {
        material->texture = s[1];
        texture_seen = true;
      } else if (s.front() == "scale" && in_first_unit && numbers(s, 2, v) && v[0] != 0.0f &&
                 v[1] != 0.0f) {
        material->scale = Eigen::Vector2f(v[0], v[1]);
      }
    }
  }
}

const std::map<std::string, ScriptMaterial>& ScriptMaterials::read(
    const std::string& folder, std::vector<std::string>& problems) {
  namespace fs = std::filesystem;
  const auto [at, first] = by_folder_.try_emplace(folder);
  if (!first) return at->second;
  std::vector<std::string> files;
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
      if (it->path().extension() == ".material") files.push_back(it->path().string());
    }
    std::sort(files.begin(), files.end());  // a name defined twice: the first file's, as listed
    if (files.size() > static_cast<std::size_t>(kMaxScriptFiles)) {
      problems.push_back("material scripts in '" + folder + "' beyond the first " +
                         std::to_string(kMaxScriptFiles));
      files.resize(kMaxScriptFiles);
    }
  } else if (fs::path(folder).extension() == ".material") {
    files.push_back(folder);
  }
  for (const std::string& file : files) {
    if (const std::string problem = fileProblem(file); !problem.empty()) {
      problems.push_back("material script '" + file + "' (it " + problem + ")");
      continue;
    }
    const std::uintmax_t size = fs::file_size(file, error);
    if (error || size > static_cast<std::uintmax_t>(kMaxScriptBytes)) {
      problems.push_back("material script '" + file + "' (over " + std::to_string(kMaxScriptBytes) +
                         " bytes)");
      continue;
    }
    if (read_bytes_ + static_cast<long>(size) > kMaxScriptTotalBytes) {
      problems.push_back("material script '" + file + "' (beyond the " +
                         std::to_string(kMaxScriptTotalBytes) + " bytes of scripts read)");
      continue;
    }
    read_bytes_ += static_cast<long>(size);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::map<std::string, ScriptMaterial> defined;
    parseMaterialScript(text.str(), defined);
    for (auto& [name, m] : defined) at->second.emplace(name, std::move(m));  // the first wins
  }
  return at->second;
}

std::optional<ScriptMaterial> ScriptMaterials::find(const std::string& name,
                                                    const std::vector<std::string>& folders,
                                                    std::vector<std::string>& problems) {
  for (const std::string& folder : folders) {
    const auto& materials = read(folder, problems);
    if (const auto it = materials.find(name); it != materials.end()) return it->second;
  }
  return std::nullopt;
}

}  // namespace jetbot_rl
