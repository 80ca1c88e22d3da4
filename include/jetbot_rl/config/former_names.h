#pragma once

#include <string>
#include <vector>

namespace jetbot_rl {

/// A parameter or program option of an earlier version, refused naming what replaced it.
struct FormerName {
  /// The old parameter, or program option (starting with "--").
  const char* name;
  /// The parameter or option that replaced it: a node refuses the old parameter when the new
  /// one is among its parameters; every program refuses the old option.
  const char* replaced_by;
  /// Why, when it was not simply renamed (else the message is "was renamed <replaced_by>").
  const char* note = "";

  /// The refusal's text: "was renamed NEW" or the note.
  std::string refusal() const { return *note ? note : std::string("was renamed ") + replaced_by; }
};

/// Every former name, the one list the parameter reader and the programs' options refuse from.
const std::vector<FormerName>& formerNames();

}  // namespace jetbot_rl
