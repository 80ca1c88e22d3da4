#pragma once

// Reading the <gazebo> blocks of a robot description (tinyxml2, as urdfdom reads the rest):
// elements by path, numbers with errors that name where they are, SDF poses.

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace gazebo_xml {

using tinyxml2::XMLElement;

/// The element at `path` (child names) below `parent`, or nullptr.
inline const XMLElement* find(const XMLElement* parent, std::initializer_list<const char*> path) {
  const XMLElement* e = parent;
  for (const char* name : path) {
    if (!e) return nullptr;
    e = e->FirstChildElement(name);
  }
  return e;
}

/// `values` numbers read from the text of `element`; ModelError naming `where` and the element.
inline std::vector<double> numbers(const XMLElement* element, std::size_t values,
                                   const std::string& where) {
  const char* text = element->GetText();
  std::istringstream s(text ? text : "");
  std::vector<double> out(values);
  for (double& v : out) {
    if (!(s >> v)) {
      throw ModelError(where + ": <" + std::string(element->Name()) + "> '" + (text ? text : "") +
                       "' must be " + std::to_string(values) +
                       (values == 1 ? " number" : " numbers"));
    }
  }
  return out;
}

/// Sets `out` from the element at `path` below `parent` when there is one.
inline void readNumber(const XMLElement* parent, std::initializer_list<const char*> path,
                       const std::string& where, double& out) {
  if (const XMLElement* e = find(parent, path)) out = numbers(e, 1, where)[0];
}

/// The text of the element at `path` below `parent`; "" when there is none.
inline std::string text(const XMLElement* parent, std::initializer_list<const char*> path) {
  const XMLElement* e = find(parent, path);
  return e && e->GetText() ? std::string(e->GetText()) : std::string();
}

/// The <pose> child of `parent` (x y z roll pitch yaw, SDF's fixed-axis order), or identity.
inline Eigen::Isometry3d pose(const XMLElement* parent, const std::string& where) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  if (const XMLElement* e = parent->FirstChildElement("pose")) {
    const std::vector<double> p = numbers(e, 6, where);
    out.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
    out.linear() = (Eigen::AngleAxisd(p[5], Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(p[4], Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(p[3], Eigen::Vector3d::UnitX()))
                       .toRotationMatrix();
  }
  return out;
}

/// Calls `visit(block)` for each <gazebo> element of URDF text, in order; none when the text does
/// not parse (urdfdom reports what is wrong with the XML).
template <typename Visit>
void forEachGazeboBlock(const std::string& urdf_xml, Visit&& visit) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS) return;
  const XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) return;
  for (const XMLElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    visit(g);
  }
}

/// True when `s` ends with `suffix`.
inline bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace gazebo_xml
}  // namespace jetbot_rl
