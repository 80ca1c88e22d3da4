#include "jetbot_rl/robot/urdf_gazebo_blocks.h"

#include <tinyxml2.h>

#include <sstream>
#include <vector>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

using tinyxml2::XMLElement;

/// The element at `path` (child names) below `parent`, or nullptr.
const XMLElement* find(const XMLElement* parent, std::initializer_list<const char*> path) {
  const XMLElement* e = parent;
  for (const char* name : path) {
    if (!e) return nullptr;
    e = e->FirstChildElement(name);
  }
  return e;
}

/// `values` numbers read from the text of `element`; ModelError naming `where` and the element.
std::vector<double> numbers(const XMLElement* element, std::size_t values,
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
void readNumber(const XMLElement* parent, std::initializer_list<const char*> path,
                const std::string& where, double& out) {
  if (const XMLElement* e = find(parent, path)) out = numbers(e, 1, where)[0];
}

std::string text(const XMLElement* parent, std::initializer_list<const char*> path) {
  const XMLElement* e = find(parent, path);
  return e && e->GetText() ? std::string(e->GetText()) : std::string();
}

GazeboRaySensor raySensor(const std::string& link, const XMLElement* sensor) {
  GazeboRaySensor ray;
  ray.link = link;
  ray.name = sensor->Attribute("name") ? sensor->Attribute("name") : "";
  const std::string where = "ray sensor '" + ray.name + "' on link '" + link + "'";
  if (const XMLElement* pose = sensor->FirstChildElement("pose")) {
    const std::vector<double> p = numbers(pose, 6, where);
    ray.pose.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
    ray.pose.linear() = (Eigen::AngleAxisd(p[5], Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(p[4], Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(p[3], Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
  }
  readNumber(sensor, {"update_rate"}, where, ray.update_rate);
  double samples = ray.samples;
  readNumber(sensor, {"ray", "scan", "horizontal", "samples"}, where, samples);
  ray.samples = static_cast<int>(samples);
  readNumber(sensor, {"ray", "scan", "horizontal", "min_angle"}, where, ray.min_angle);
  readNumber(sensor, {"ray", "scan", "horizontal", "max_angle"}, where, ray.max_angle);
  readNumber(sensor, {"ray", "range", "min"}, where, ray.range_min);
  readNumber(sensor, {"ray", "range", "max"}, where, ray.range_max);
  if (text(sensor, {"ray", "noise", "type"}) == "gaussian") {
    readNumber(sensor, {"ray", "noise", "mean"}, where, ray.noise_mean);
    readNumber(sensor, {"ray", "noise", "stddev"}, where, ray.noise_stddev);
  }
  return ray;
}

GazeboDiffDrive diffDrive(const XMLElement* plugin) {
  GazeboDiffDrive drive;
  const std::string where =
      std::string("plugin '") + (plugin->Attribute("name") ? plugin->Attribute("name") : "") + "'";
  // ROS 1's gazebo_ros_diff_drive names, then ROS 2's (gazebo_ros_pkgs 3.x).
  const auto name = [&](const char* ros1, const char* ros2) {
    const std::string v = text(plugin, {ros1});
    return v.empty() ? text(plugin, {ros2}) : v;
  };
  const auto number = [&](const char* ros1, const char* ros2, double& out) {
    readNumber(plugin, {ros2}, where, out);
    readNumber(plugin, {ros1}, where, out);
  };
  drive.left_joint = name("leftJoint", "left_joint");
  drive.right_joint = name("rightJoint", "right_joint");
  number("wheelSeparation", "wheel_separation", drive.wheel_separation);
  number("wheelDiameter", "wheel_diameter", drive.wheel_diameter);
  number("wheelTorque", "max_wheel_torque", drive.wheel_torque);
  return drive;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

GazeboBlocks parseGazeboBlocks(const std::string& urdf_xml) {
  GazeboBlocks blocks;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS) {
    return blocks;  // urdfdom reports what is wrong with the XML
  }
  const XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) return blocks;
  for (const XMLElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    const char* reference = g->Attribute("reference");
    for (const XMLElement* s = g->FirstChildElement("sensor"); s && reference && !blocks.ray;
         s = s->NextSiblingElement("sensor")) {
      const char* type = s->Attribute("type");
      if (type && (std::string(type) == "ray" || std::string(type) == "gpu_ray")) {
        blocks.ray = raySensor(reference, s);
      }
    }
    for (const XMLElement* p = g->FirstChildElement("plugin"); p && !blocks.diff_drive;
         p = p->NextSiblingElement("plugin")) {
      const char* file = p->Attribute("filename");
      if (file && endsWith(file, "gazebo_ros_diff_drive.so")) blocks.diff_drive = diffDrive(p);
    }
  }
  return blocks;
}

}  // namespace jetbot_rl
