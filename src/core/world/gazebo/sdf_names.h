#pragma once

// The names of SDF elements as the passes before sdformat read them (tinyxml2).

#include <tinyxml2.h>

#include <string>

namespace jetbot_rl {

/// `e`'s name attribute, or "" (also for no element).
inline std::string nameAttribute(const tinyxml2::XMLElement* e) {
  const char* name = e ? e->Attribute("name") : nullptr;
  return name ? name : "";
}

/// The name of a world's <model> (its attribute) or <include> (its <name>), or "".
inline std::string entityName(const tinyxml2::XMLElement& e) {
  if (std::string(e.Name()) == "model") return nameAttribute(&e);
  const tinyxml2::XMLElement* n = e.FirstChildElement("name");
  return n && n->GetText() ? n->GetText() : "";
}

}  // namespace jetbot_rl
