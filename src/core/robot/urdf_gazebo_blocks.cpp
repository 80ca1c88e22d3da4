#include "jetbot_rl/robot/urdf_gazebo_blocks.h"

#include <tinyxml2.h>

#include "robot/gazebo_xml.h"

namespace jetbot_rl {
namespace {

GazeboRaySensor raySensor(const std::string& link, const tinyxml2::XMLElement* sensor) {
  GazeboRaySensor ray;
  ray.link = link;
  ray.name = sensor->Attribute("name") ? sensor->Attribute("name") : "";
  const std::string where = "ray sensor '" + ray.name + "' on link '" + link + "'";
  ray.pose = gazebo_xml::pose(sensor, where);
  gazebo_xml::readNumber(sensor, {"update_rate"}, where, ray.update_rate);
  double samples = ray.samples;
  gazebo_xml::readNumber(sensor, {"ray", "scan", "horizontal", "samples"}, where, samples);
  ray.samples = static_cast<int>(samples);
  gazebo_xml::readNumber(sensor, {"ray", "scan", "horizontal", "min_angle"}, where, ray.min_angle);
  gazebo_xml::readNumber(sensor, {"ray", "scan", "horizontal", "max_angle"}, where, ray.max_angle);
  gazebo_xml::readNumber(sensor, {"ray", "range", "min"}, where, ray.range_min);
  gazebo_xml::readNumber(sensor, {"ray", "range", "max"}, where, ray.range_max);
  if (gazebo_xml::text(sensor, {"ray", "noise", "type"}) == "gaussian") {
    gazebo_xml::readNumber(sensor, {"ray", "noise", "mean"}, where, ray.noise_mean);
    gazebo_xml::readNumber(sensor, {"ray", "noise", "stddev"}, where, ray.noise_stddev);
  }
  return ray;
}

GazeboDiffDrive diffDrive(const tinyxml2::XMLElement* plugin) {
  GazeboDiffDrive drive;
  const std::string where =
      std::string("plugin '") + (plugin->Attribute("name") ? plugin->Attribute("name") : "") + "'";
  // ROS 1's gazebo_ros_diff_drive names, then ROS 2's (gazebo_ros_pkgs 3.x).
  const auto name = [&](const char* ros1, const char* ros2) {
    const std::string v = gazebo_xml::text(plugin, {ros1});
    return v.empty() ? gazebo_xml::text(plugin, {ros2}) : v;
  };
  const auto number = [&](const char* ros1, const char* ros2, double& out) {
    gazebo_xml::readNumber(plugin, {ros2}, where, out);
    gazebo_xml::readNumber(plugin, {ros1}, where, out);
  };
  drive.left_joint = name("leftJoint", "left_joint");
  drive.right_joint = name("rightJoint", "right_joint");
  number("wheelSeparation", "wheel_separation", drive.wheel_separation);
  number("wheelDiameter", "wheel_diameter", drive.wheel_diameter);
  number("wheelTorque", "max_wheel_torque", drive.wheel_torque);
  return drive;
}

}  // namespace

GazeboBlocks parseGazeboBlocks(const std::string& urdf_xml) {
  GazeboBlocks blocks;
  gazebo_xml::forEachGazeboBlock(urdf_xml, [&blocks](const tinyxml2::XMLElement* g) {
    const char* reference = g->Attribute("reference");
    for (const tinyxml2::XMLElement* s = g->FirstChildElement("sensor");
         s && reference && !blocks.ray; s = s->NextSiblingElement("sensor")) {
      const char* type = s->Attribute("type");
      if (type && (std::string(type) == "ray" || std::string(type) == "gpu_ray")) {
        blocks.ray = raySensor(reference, s);
      }
    }
    for (const tinyxml2::XMLElement* p = g->FirstChildElement("plugin"); p && !blocks.diff_drive;
         p = p->NextSiblingElement("plugin")) {
      const char* file = p->Attribute("filename");
      if (file && gazebo_xml::endsWith(file, "gazebo_ros_diff_drive.so")) {
        blocks.diff_drive = diffDrive(p);
      }
    }
  });
  blocks.cameras = parseCameraBlocks(urdf_xml);
  return blocks;
}

}  // namespace jetbot_rl
