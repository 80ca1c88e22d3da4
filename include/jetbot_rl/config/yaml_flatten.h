#pragma once

#include <string>

namespace jetbot_rl {

/**
 * A YAML parameter file as the "key: value" lines fieldsFromYaml() reads, parsed by yaml-cpp as
 * rosparam parses it: nested maps become "block/key", every list (flow `[a, b]` or block
 * `- a`) becomes "[a, b]", an empty value (null) is left out. Throws ConfigError naming the line
 * for text that is no YAML, and the key for a list holding lists or maps (no parameter is one);
 * the caller names the file.
 */
std::string flattenYaml(const std::string& yaml);

}  // namespace jetbot_rl
