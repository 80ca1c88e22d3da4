#include "jetbot_rl/yaml_flatten.h"

#include <yaml-cpp/yaml.h>

#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

void flatten(const YAML::Node& node, const std::string& key, const std::string& source,
             std::ostringstream& out) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      for (const auto& child : node) {
        const std::string name = child.first.as<std::string>();
        flatten(child.second, key.empty() ? name : key + "/" + name, source, out);
      }
      break;
    case YAML::NodeType::Sequence: {
      out << key << ": [";
      for (std::size_t i = 0; i < node.size(); ++i) {
        if (!node[i].IsScalar()) {
          throw ConfigError(source + ": " + key + " holds a list or a map as item " +
                            std::to_string(i) + ": a parameter's list holds values");
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

std::string flattenYaml(const std::string& yaml, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source + ": no YAML at line " + std::to_string(e.mark.line + 1) + ": " +
                      e.msg);
  }
  if (!root.IsMap() && !root.IsNull()) {
    throw ConfigError(source + ": a parameter file holds a map of names to values");
  }
  std::ostringstream out;
  flatten(root, "", source, out);
  return out.str();
}

}  // namespace jetbot_rl
