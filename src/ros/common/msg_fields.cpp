#include "jetbot_rl/ros/common/msg_fields.h"

#include <sstream>

namespace jetbot_rl {

std::vector<std::string> msgFieldNames(const std::string& definition) {
  std::vector<std::string> names;
  std::istringstream lines(definition);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("===", 0) == 0) break;  // the definitions of nested types follow
    const std::size_t comment = line.find('#');
    if (comment != std::string::npos) line.erase(comment);
    std::istringstream words(line);
    std::string type, name, rest;
    if (!(words >> type)) continue;                     // blank or a comment
    if (line.find('=') != std::string::npos) continue;  // a constant
    if (!(words >> name) || (words >> rest)) {
      throw Error("cannot read the message definition line '" + line + "'");
    }
    names.push_back(name);
  }
  return names;
}

}  // namespace jetbot_rl
