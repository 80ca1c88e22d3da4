// Plain models read without sdformat (plain_models.h).
#include "world/gazebo/plain_models.h"

#include <cmath>
#include <initializer_list>
#include <sdf/Box.hh>
#include <sdf/Cylinder.hh>
#include <sdf/Sphere.hh>
#include <set>
#include <sstream>

#include "world/gazebo/inertia_free_models.h"

namespace jetbot_rl {
namespace {

/// True when `name` is one of `allowed`.
bool oneOf(const char* name, std::initializer_list<const char*> allowed) {
  for (const char* a : allowed) {
    if (std::string(name) == a) return true;
  }
  return false;
}

/// True when `e` has no attributes but those in `allowed`.
bool onlyAttributes(const tinyxml2::XMLElement& e, std::initializer_list<const char*> allowed) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    if (!oneOf(a->Name(), allowed)) return false;
  }
  return true;
}

/// True when every child element of `e` has one of the `allowed` tags.
bool onlyChildren(const tinyxml2::XMLElement& e, std::initializer_list<const char*> allowed) {
  for (const tinyxml2::XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (!oneOf(c->Name(), allowed)) return false;
  }
  return true;
}

/// The finite numbers of `e`'s text, as sdformat's parameters read them (stream extraction);
/// false for anything else or a count other than one in `counts`.
bool numbers(const tinyxml2::XMLElement* e, std::initializer_list<std::size_t> counts,
             std::vector<double>& out, bool attributes = false) {
  out.clear();
  if (!e || (!attributes && !onlyAttributes(*e, {})) || e->FirstChildElement()) return false;
  std::istringstream s(e->GetText() ? e->GetText() : "");
  for (double v; s >> v;) {
    if (!std::isfinite(v)) return false;
    out.push_back(v);
  }
  if (!s.eof()) return false;  // a word that is not a number
  for (std::size_t n : counts) {
    if (out.size() == n) return true;
  }
  return false;
}

/// The one child <tag> of `e`, or null when there is none or more than one.
const tinyxml2::XMLElement* only(const tinyxml2::XMLElement& e, const char* tag) {
  const tinyxml2::XMLElement* c = e.FirstChildElement(tag);
  return c && !c->NextSiblingElement(tag) ? c : nullptr;
}

/// A <geometry> of one box, cylinder or sphere, each with its numbers and nothing else.
bool readGeometry(const tinyxml2::XMLElement& e, sdf::Geometry& out) {
  const tinyxml2::XMLElement* shape = e.FirstChildElement();
  if (!onlyAttributes(e, {}) || !shape || shape->NextSiblingElement() ||
      !onlyAttributes(*shape, {})) {
    return false;
  }
  const std::string tag = shape->Name();
  std::vector<double> a, b;
  if (tag == "box" && onlyChildren(*shape, {"size"}) && numbers(only(*shape, "size"), {3}, a)) {
    sdf::Box box;
    box.SetSize({a[0], a[1], a[2]});
    out.SetType(sdf::GeometryType::BOX);
    out.SetBoxShape(box);
    return true;
  }
  if (tag == "cylinder" && onlyChildren(*shape, {"radius", "length"}) &&
      numbers(only(*shape, "radius"), {1}, a) && numbers(only(*shape, "length"), {1}, b)) {
    sdf::Cylinder cylinder;
    cylinder.SetRadius(a[0]);
    cylinder.SetLength(b[0]);
    out.SetType(sdf::GeometryType::CYLINDER);
    out.SetCylinderShape(cylinder);
    return true;
  }
  if (tag == "sphere" && onlyChildren(*shape, {"radius"}) &&
      numbers(only(*shape, "radius"), {1}, a)) {
    sdf::Sphere sphere;
    sphere.SetRadius(a[0]);
    out.SetType(sdf::GeometryType::SPHERE);
    out.SetSphereShape(sphere);
    return true;
  }
  return false;
}

/// The colour in `e` (3 or 4 numbers in [0, 1]) read as sdformat reads a colour (floats).
bool colour(const tinyxml2::XMLElement& e, Eigen::Vector3f& rgb) {
  if (!onlyAttributes(e, {}) || e.FirstChildElement()) return false;
  std::istringstream s(e.GetText() ? e.GetText() : "");
  std::vector<float> v;
  for (float x; s >> x;) {
    if (!(x >= 0.0f && x <= 1.0f)) return false;
    v.push_back(x);
  }
  if (!s.eof() || (v.size() != 3 && v.size() != 4)) return false;
  rgb = Eigen::Vector3f(v[0], v[1], v[2]);
  return true;
}

/// A <material> of colours and a Gazebo <script> (a <name> and <uri>s), as scripts write them.
bool readMaterial(const tinyxml2::XMLElement& e, VisualMaterial& out) {
  if (!onlyAttributes(e, {}) ||
      !onlyChildren(e, {"ambient", "diffuse", "specular", "emissive", "script"})) {
    return false;
  }
  for (const tinyxml2::XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (c->NextSiblingElement(c->Name())) return false;  // each once
    Eigen::Vector3f rgb;
    if (std::string(c->Name()) != "script") {
      if (!colour(*c, rgb)) return false;
      if (std::string(c->Name()) == "diffuse") out.diffuse = rgb;
      continue;
    }
    const tinyxml2::XMLElement* name = only(*c, "name");
    if (!onlyAttributes(*c, {}) || !onlyChildren(*c, {"name", "uri"}) || !name ||
        name->FirstChildElement() || !onlyAttributes(*name, {}) || !name->GetText()) {
      return false;
    }
    // sdformat wants a <uri> (a script's file) that is not empty.
    if (!c->FirstChildElement("uri")) return false;
    for (const tinyxml2::XMLElement* u = c->FirstChildElement("uri"); u;
         u = u->NextSiblingElement("uri")) {
      if (u->FirstChildElement() || !onlyAttributes(*u, {}) || !u->GetText()) return false;
      std::string uri = u->GetText();  // as sdformat reads it: without surrounding spaces
      uri.erase(0, uri.find_first_not_of(" \t\r\n"));
      uri.erase(uri.find_last_not_of(" \t\r\n") + 1);
      out.script_uris.push_back(uri);
    }
    out.script = name->GetText();
  }
  return true;
}

/// A <collision> or <visual> with a name, a plain pose and geometry (a visual may have a
/// material of colours and a script).
bool readShape(const tinyxml2::XMLElement& e, bool visual, PlainShape& out) {
  const char* name = e.Attribute("name");
  const tinyxml2::XMLElement* geometry = only(e, "geometry");
  const tinyxml2::XMLElement* material = e.FirstChildElement("material");
  if (!name || !ordinaryName(name) || !onlyAttributes(e, {"name"}) || !geometry ||
      !onlyChildren(e, visual ? std::initializer_list<const char*>{"pose", "geometry", "material"}
                              : std::initializer_list<const char*>{"pose", "geometry"}) ||
      (material &&
       (material->NextSiblingElement("material") || !readMaterial(*material, out.material)))) {
    return false;
  }
  out.name = name;
  out.line = e.GetLineNum();
  return readPlainPose(e, out.pose) && readGeometry(*geometry, out.geometry);
}

/// An <inertial> of numbers only: its <mass>, <inertia> moments and <pose>.
bool plainInertial(const tinyxml2::XMLElement& e) {
  std::vector<double> v;
  ignition::math::Pose3d pose;
  if (!onlyAttributes(e, {}) || !onlyChildren(e, {"mass", "inertia", "pose"}) ||
      !readPlainPose(e, pose)) {
    return false;
  }
  if (const tinyxml2::XMLElement* mass = e.FirstChildElement("mass");
      mass && (mass->NextSiblingElement("mass") || !numbers(mass, {1}, v))) {
    return false;
  }
  const tinyxml2::XMLElement* inertia = e.FirstChildElement("inertia");
  if (!inertia) return true;
  if (inertia->NextSiblingElement("inertia") || !onlyAttributes(*inertia, {}) ||
      !onlyChildren(*inertia, {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"})) {
    return false;
  }
  std::set<std::string> seen;
  for (const tinyxml2::XMLElement* c = inertia->FirstChildElement(); c;
       c = c->NextSiblingElement()) {
    if (!seen.insert(c->Name()).second || !numbers(c, {1}, v)) return false;
  }
  return true;
}

}  // namespace

bool ordinaryName(const std::string& name) {
  const bool reserved =
      name.size() >= 4 && name.rfind("__", 0) == 0 && name.compare(name.size() - 2, 2, "__") == 0;
  return !name.empty() && name.find("::") == std::string::npos && !reserved && name != "world";
}

bool readPlainPose(const tinyxml2::XMLElement& parent, ignition::math::Pose3d& pose) {
  const tinyxml2::XMLElement* e = parent.FirstChildElement("pose");
  if (!e) {
    pose = ignition::math::Pose3d::Zero;
    return true;
  }
  // frame='' (as Gazebo 9 saved worlds write it) or relative_to='': the default frame.
  for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
    if (!oneOf(a->Name(), {"frame", "relative_to"}) || a->Value()[0] != '\0') return false;
  }
  std::vector<double> v;
  if (e->NextSiblingElement("pose") || !numbers(e, {6}, v, /*attributes=*/true)) return false;
  pose = ignition::math::Pose3d(v[0], v[1], v[2], v[3], v[4], v[5]);
  return true;
}

bool readPlainModel(tinyxml2::XMLElement& model, const std::string& file, bool visuals,
                    PlainModel& out) {
  const char* name = model.Attribute("name");
  if (!name || !ordinaryName(name) || !onlyAttributes(model, {"name"}) ||
      !onlyChildren(model, {"static", "pose", "link"}) || !model.FirstChildElement("link") ||
      !readPlainPose(model, out.pose)) {
    return false;
  }
  if (const tinyxml2::XMLElement* s = model.FirstChildElement("static")) {
    const std::string text = s->GetText() ? s->GetText() : "";
    if (s->NextSiblingElement("static") || s->FirstChildElement() || !onlyAttributes(*s, {}) ||
        (text != "true" && text != "false" && text != "1" && text != "0")) {
      return false;
    }
  }
  out.name = name;
  out.links.clear();
  out.warnings.clear();
  std::set<std::string> link_names;
  for (const tinyxml2::XMLElement* l = model.FirstChildElement("link"); l;
       l = l->NextSiblingElement("link")) {
    PlainLink link;
    const char* link_name = l->Attribute("name");
    if (!link_name || !ordinaryName(link_name) || !link_names.insert(link_name).second ||
        !onlyAttributes(*l, {"name"}) ||
        !onlyChildren(*l, {"pose", "collision", "visual", "inertial"}) ||
        !readPlainPose(*l, link.pose)) {
      return false;
    }
    link.name = link_name;
    std::set<std::string> shape_names[2];
    for (const tinyxml2::XMLElement* c = l->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "inertial") {
        if (c->NextSiblingElement("inertial") || !plainInertial(*c)) return false;
        continue;
      }
      if (tag != "collision" && tag != "visual") continue;
      const bool visual = tag == "visual";
      PlainShape shape;
      if (!readShape(*c, visual, shape) || !shape_names[visual].insert(shape.name).second) {
        return false;
      }
      if (!visual) {
        link.collisions.push_back(std::move(shape));
      } else if (visuals) {
        link.visuals.push_back(std::move(shape));
      }
    }
    out.links.push_back(std::move(link));
  }
  // sdformat refuses some inertias that Gazebo 11 loads: judged and named as for sdformat's
  // models (inertia_free_models.h).
  stripInertials(model, file, out.warnings);
  return true;
}

}  // namespace jetbot_rl
