#include "jetbot_rl/robot/urdf_camera_blocks.h"

#include <tinyxml2.h>

#include <cmath>
#include <utility>

#include "robot/gazebo_xml.h"

namespace jetbot_rl {
namespace {

CameraFormat cameraFormat(const std::string& format, const std::string& where) {
  if (format.empty() || format == "R8G8B8" || format == "RGB_INT8") return CameraFormat::kRgb8;
  if (format == "B8G8R8" || format == "BGR_INT8") return CameraFormat::kBgr8;
  if (format == "L8" || format == "L_INT8") return CameraFormat::kMono8;
  throw ModelError(where + ": <image><format> '" + format +
                   "' is not one a camera here renders (R8G8B8, B8G8R8 or L8)");
}

/// What a <camera> element gives, over `camera` (the sensor's values so far).
void readCamera(const tinyxml2::XMLElement* element, const std::string& where,
                GazeboCamera& camera) {
  camera.pose = camera.pose * gazebo_xml::pose(element, where);
  CameraIntrinsics& c = camera.intrinsics;
  c = CameraIntrinsics();
  // SDF's defaults: 320 x 240, 1.047 rad, clip 0.1 to 100 m.
  c.width = 320;
  c.height = 240;
  c.near = 0.1;
  c.far = 100.0;
  gazebo_xml::readNumber(element, {"horizontal_fov"}, where, c.horizontal_fov);
  double width = c.width, height = c.height;
  gazebo_xml::readNumber(element, {"image", "width"}, where, width);
  gazebo_xml::readNumber(element, {"image", "height"}, where, height);
  for (const auto& [name, size] :
       {std::pair<const char*, double>{"width", width}, {"height", height}}) {
    if (!(size >= 1.0 && size <= kMaxImageSide && size == std::floor(size))) {
      throwInvalid(where + ": " + name, size, "must be a whole number in [1, 4096] px");
    }
  }
  c.width = static_cast<int>(width);
  c.height = static_cast<int>(height);
  camera.format = cameraFormat(gazebo_xml::text(element, {"image", "format"}), where);
  gazebo_xml::readNumber(element, {"clip", "near"}, where, c.near);
  gazebo_xml::readNumber(element, {"clip", "far"}, where, c.far);
  gazebo_xml::readNumber(element, {"distortion", "k1"}, where, c.k1);
  gazebo_xml::readNumber(element, {"distortion", "k2"}, where, c.k2);
  gazebo_xml::readNumber(element, {"distortion", "k3"}, where, c.k3);
  gazebo_xml::readNumber(element, {"distortion", "p1"}, where, c.p1);
  gazebo_xml::readNumber(element, {"distortion", "p2"}, where, c.p2);
  if (gazebo_xml::text(element, {"noise", "type"}) == "gaussian") {
    gazebo_xml::readNumber(element, {"noise", "mean"}, where, camera.noise_mean);
    gazebo_xml::readNumber(element, {"noise", "stddev"}, where, camera.noise_stddev);
  }
  validateIntrinsics(c, where + ": ");
}

/// The ROS plugin's elements (ROS 1 gazebo_ros_pkgs names).
void readPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                GazeboCamera& camera) {
  camera.plugin = plugin->Attribute("filename") ? plugin->Attribute("filename") : "";
  camera.camera_topic = gazebo_xml::text(plugin, {"cameraName"});
  camera.image_topic = gazebo_xml::text(plugin, {"imageTopicName"});
  camera.info_topic = gazebo_xml::text(plugin, {"cameraInfoTopicName"});
  camera.depth_image_topic = gazebo_xml::text(plugin, {"depthImageTopicName"});
  camera.depth_info_topic = gazebo_xml::text(plugin, {"depthImageCameraInfoTopicName"});
  if (camera.depth_info_topic.empty()) {
    camera.depth_info_topic = gazebo_xml::text(plugin, {"depthImageInfoTopicName"});
  }
  camera.frame_name = gazebo_xml::text(plugin, {"frameName"});
  gazebo_xml::readNumber(plugin, {"updateRate"}, where, camera.plugin_update_rate);
}

bool isCameraPlugin(const tinyxml2::XMLElement* plugin) {
  const char* file = plugin->Attribute("filename");
  if (!file) return false;
  for (const char* known : {"gazebo_ros_camera.so", "gazebo_ros_openni_kinect.so",
                            "gazebo_ros_depth_camera.so", "gazebo_ros_multicamera.so"}) {
    if (gazebo_xml::endsWith(file, known)) return true;
  }
  return false;
}

}  // namespace

std::vector<GazeboCamera> parseCameraBlocks(const std::string& urdf_xml) {
  std::vector<GazeboCamera> cameras;
  gazebo_xml::forEachGazeboBlock(urdf_xml, [&cameras](const tinyxml2::XMLElement* g) {
    const char* reference = g->Attribute("reference");
    if (!reference) return;
    for (const tinyxml2::XMLElement* s = g->FirstChildElement("sensor"); s;
         s = s->NextSiblingElement("sensor")) {
      const std::string type = s->Attribute("type") ? s->Attribute("type") : "";
      if (type != "camera" && type != "depth" && type != "multicamera") continue;
      GazeboCamera sensor;
      sensor.link = reference;
      sensor.type = type;
      sensor.sensor_name = s->Attribute("name") ? s->Attribute("name") : "";
      const std::string where =
          type + " sensor '" + sensor.sensor_name + "' on link '" + sensor.link + "'";
      sensor.pose = gazebo_xml::pose(s, where);
      gazebo_xml::readNumber(s, {"update_rate"}, where, sensor.update_rate);
      for (const tinyxml2::XMLElement* p = s->FirstChildElement("plugin"); p;
           p = p->NextSiblingElement("plugin")) {
        if (isCameraPlugin(p)) {
          readPlugin(p, where, sensor);
          break;
        }
      }
      // A camera or depth sensor has one <camera>; a multicamera one per camera.
      const tinyxml2::XMLElement* first = s->FirstChildElement("camera");
      if (!first) throw ModelError(where + ": no <camera> element");
      for (const tinyxml2::XMLElement* c = first; c; c = c->NextSiblingElement("camera")) {
        GazeboCamera camera = sensor;
        camera.camera_name = c->Attribute("name") ? c->Attribute("name") : "";
        readCamera(
            c, camera.camera_name.empty() ? where : where + ", camera '" + camera.camera_name + "'",
            camera);
        cameras.push_back(camera);
        if (type != "multicamera") break;
      }
    }
  });
  return cameras;
}

}  // namespace jetbot_rl
