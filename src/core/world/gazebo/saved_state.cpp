// A saved world's <state>, as Gazebo 11 applies it at load (saved_state.h).
#include "world/gazebo/saved_state.h"

#include <set>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "world/gazebo/sdf_names.h"
#include "world/gazebo/sdf_shapes.h"

namespace jetbot_rl {
namespace {

/// The <pose> of `e` ("x y z roll pitch yaw"; the identity without one) in the world frame.
Eigen::Isometry3d poseOf(const tinyxml2::XMLElement& e, const std::string& path) {
  const tinyxml2::XMLElement* pose = e.FirstChildElement("pose");
  if (!pose) return Eigen::Isometry3d::Identity();
  std::istringstream in(pose->GetText() ? pose->GetText() : "");
  double v[6];
  for (double& x : v) in >> x;
  std::string rest;
  if (!in || (in >> rest)) {
    throw ConfigError(path + ":" + std::to_string(pose->GetLineNum()) + ": <state> pose '" +
                      (pose->GetText() ? pose->GetText() : "") +
                      "' is not six numbers (x y z roll pitch yaw)");
  }
  // As sdformat reads a pose (ignition's roll, pitch, yaw): the same transform bit for bit.
  return toEigen(ignition::math::Pose3d(v[0], v[1], v[2], v[3], v[4], v[5]));
}

/// A model state and its nested ones: their poses and links' poses under `scope`.
void readModel(const tinyxml2::XMLElement& m, const std::string& scope, const std::string& path,
               SavedState& state) {
  const std::string name = scope.empty() ? nameAttribute(&m) : scope + "::" + nameAttribute(&m);
  if (m.FirstChildElement("pose")) state.models[name] = poseOf(m, path);
  if (const tinyxml2::XMLElement* scale = m.FirstChildElement("scale")) {
    std::istringstream in(scale->GetText() ? scale->GetText() : "");
    double x = 1, y = 1, z = 1;
    in >> x >> y >> z;
    if (!in || x != 1.0 || y != 1.0 || z != 1.0) {
      state.scaled.push_back(path + ":" + std::to_string(scale->GetLineNum()) + ": model '" + name +
                             "'");
    }
  }
  for (const tinyxml2::XMLElement* l = m.FirstChildElement("link"); l;
       l = l->NextSiblingElement("link")) {
    if (l->FirstChildElement("pose"))
      state.links[name + "::" + nameAttribute(l)] = poseOf(*l, path);
  }
  for (const tinyxml2::XMLElement* n = m.FirstChildElement("model"); n;
       n = n->NextSiblingElement("model")) {
    readModel(*n, name, path, state);
  }
}

}  // namespace

SavedState takeSavedState(tinyxml2::XMLElement& world, const std::string& path, bool& changed) {
  changed = false;
  SavedState state;
  tinyxml2::XMLElement* saved = world.FirstChildElement("state");
  if (!saved) return state;
  // Inserted models join the world (Gazebo loads them, then poses every model).
  if (const tinyxml2::XMLElement* insertions = saved->FirstChildElement("insertions")) {
    for (const tinyxml2::XMLElement* m = insertions->FirstChildElement("model"); m;
         m = m->NextSiblingElement("model")) {
      world.InsertEndChild(m->DeepClone(world.GetDocument()));
      changed = true;
    }
  }
  for (const tinyxml2::XMLElement* m = saved->FirstChildElement("model"); m;
       m = m->NextSiblingElement("model")) {
    readModel(*m, "", path, state);
  }
  std::set<std::string> deleted;
  if (const tinyxml2::XMLElement* deletions = saved->FirstChildElement("deletions")) {
    for (const tinyxml2::XMLElement* n = deletions->FirstChildElement("name"); n;
         n = n->NextSiblingElement("name")) {
      if (n->GetText()) deleted.insert(n->GetText());
    }
  }
  for (tinyxml2::XMLElement* e = world.FirstChildElement(); e;) {
    tinyxml2::XMLElement* next = e->NextSiblingElement();
    const std::string tag = e->Name();
    if (tag == "state" || ((tag == "model" || tag == "include") && deleted.count(entityName(*e)))) {
      changed = changed || tag != "state";
      world.DeleteChild(e);
    }
    e = next;
  }
  return state;
}

}  // namespace jetbot_rl
