#include "jetbot_rl/config/yaml_flatten.h"

#include <yaml-cpp/yaml.h>

#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

void flatten(const YAML::Node& node, const std::string& key, std::ostringstream& out) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      for (const auto& child : node) {
        const std::string name = child.first.as<std::string>();
        flatten(child.second, key.empty() ? name : key + "/" + name, out);
      }
      break;
    case YAML::NodeType::Sequence: {
      out << key << ": [";
      for (std::size_t i = 0; i < node.size(); ++i) {
        if (!node[i].IsScalar()) {
          throw ConfigError(key + " holds a list or a map as item " + std::to_string(i) +
                            ": a parameter's list holds values");
        }
        out << (i ? ", " : "") << node[i].Scalar();
      }
      out << "]\n";
      break;
    }
    case YAML::NodeType::Scalar:
      // An empty string stays one ('' as the line reader reads it), not a value left out.
      out << key << ": " << (node.Scalar().empty() ? "''" : node.Scalar()) << "\n";
      break;
    default:  // null, undefined: no value given
      break;
  }
}

}  // namespace

std::string flattenYaml(const std::string& yaml) {
  std::ostringstream out;
  try {
    const YAML::Node root = YAML::Load(yaml);
    if (!root.IsMap() && !root.IsNull()) {
      throw ConfigError("a parameter file holds a map of names to values");
    }
    flatten(root, "", out);
  } catch (const YAML::Exception& e) {  // not YAML, or a key that is no name
    throw ConfigError("no YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  return out.str();
}

}  // namespace jetbot_rl
