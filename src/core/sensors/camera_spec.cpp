#include "jetbot_rl/sensors/camera_spec.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/camera_scene.h"

namespace jetbot_rl {
namespace {

/// `name` under the namespace `space` ("a" + "b/c": "a/b/c"); a name that starts with '/' is
/// absolute in Gazebo: here it is relative to the robot's namespace.
std::string joinTopic(const std::string& space, const std::string& name) {
  if (!name.empty() && name.front() == '/') return name.substr(1);
  return space.empty() ? name : space + "/" + name;
}

const char* const kImageNames[] = {"rgb", "depth", "label"};

}  // namespace

void checkFieldRules(const CameraConfig& c) {
  if (!c.clip.empty() && c.clip.size() != 2) {
    throwInvalid("camera/clip", listText(c.clip), "must be [near, far] or []");
  }
  if (!c.distortion.empty() && c.distortion.size() != 5) {
    throwInvalid("camera/distortion", listText(c.distortion), "must be [k1, k2, k3, p1, p2] or []");
  }
  if (c.noise_std < 0.0 && c.noise_std != -1.0) {
    throwInvalid("camera/noise_std", c.noise_std, "must be -1 (the block's) or >= 0");
  }
  for (const auto& [name, range] : {std::make_pair("camera/light_intensity", &c.light_intensity),
                                    std::make_pair("camera/exposure", &c.exposure)}) {
    if (!range->empty() && (range->size() != 2 || (*range)[0] > (*range)[1])) {
      throwInvalid(name, listText(*range), "must be [min, max] with min <= max, or []");
    }
  }
  if (!c.pose_jitter.empty() && c.pose_jitter.size() != 2) {
    throwInvalid("camera/pose_jitter", listText(c.pose_jitter),
                 "must be [position m, angle rad] or []");
  }
  for (const std::string& image : c.images) {
    if (std::find(std::begin(kImageNames), std::end(kImageNames), image) == std::end(kImageNames)) {
      throwInvalid("camera/images", "'" + image + "'", "must be rgb, depth or label");
    }
  }
}

namespace {

/// Where gazebo_ros_multicamera publishes camera `g` of a multicamera: "left" or "right" when its
/// name holds one of them, else (where Gazebo publishes nothing) its name.
std::string multicameraSuffix(const GazeboCamera& g) {
  for (const char* side : {"left", "right"}) {
    if (g.camera_name.find(side) != std::string::npos) return side;
  }
  return g.camera_name.empty() ? g.sensor_name : g.camera_name;
}

/// The camera of block `g` (nullptr: one of the parameters alone on camera/link) on `robot`.
CameraSpec resolveOne(const CameraConfig& config, const RobotModel& robot, const GazeboCamera* g,
                      double control_dt) {
  CameraSpec spec;
  spec.link = g ? g->link : config.link;
  spec.link_from = config.link.empty() ? "Gazebo" : "camera/link";
  Eigen::Isometry3d offset;
  if (!robot.findLink(spec.link, spec.body, offset)) {
    if (!config.link.empty()) {
      throwInvalid("camera/link", "'" + spec.link + "'", "is not a link of the robot description");
    }
    throw ModelError("the Gazebo " + g->type + " sensor '" + g->sensor_name + "' is on link '" +
                     g->link + "', which is not a link of the robot description");
  }
  spec.name = !g                         ? "camera"
              : g->type == "multicamera" ? g->sensor_name + "/" + g->camera_name
                                         : g->sensor_name;
  const std::string gazebo = g ? " (from the Gazebo " + g->type + " sensor '" + g->sensor_name +
                                     "' of link '" + g->link +
                                     "'; set the parameter to override it)"
                               : "";
  const auto pick = [&](bool set, const char* name) {
    return set ? std::string(name) : g ? std::string("Gazebo") : std::string("default");
  };
  spec.pose_in_body = offset * (g ? g->pose : Eigen::Isometry3d::Identity());
  spec.optical_in_link = opticalFrame(g ? g->pose : Eigen::Isometry3d::Identity());
  spec.sensor_name = g ? g->sensor_name : "";
  spec.shadows = config.shadows;
  spec.random_colours = config.random_colours;
  spec.random_light_direction = config.random_light_direction;
  spec.light_intensity = config.light_intensity;
  spec.exposure = config.exposure;
  spec.pose_jitter = config.pose_jitter;

  CameraIntrinsics& c = spec.intrinsics;
  if (g) c = g->intrinsics;  // else CameraIntrinsics' defaults: 64 x 64, 1.047 rad, [0.05, 10]
  if (config.width > 0) c.width = config.width;
  if (config.height > 0) c.height = config.height;
  spec.size_from = pick(config.width > 0 || config.height > 0, "camera/width, camera/height");
  if (config.horizontal_fov > 0.0) c.horizontal_fov = config.horizontal_fov;
  spec.fov_from = pick(config.horizontal_fov > 0.0, "camera/horizontal_fov");
  if (config.clip.size() == 2) {
    c.near = config.clip[0];
    c.far = config.clip[1];
  }
  spec.clip_from = pick(config.clip.size() == 2, "camera/clip");
  if (config.distortion.size() == 5) {
    c.k1 = config.distortion[0];
    c.k2 = config.distortion[1];
    c.k3 = config.distortion[2];
    c.p1 = config.distortion[3];
    c.p2 = config.distortion[4];
  }
  spec.distortion_from = pick(config.distortion.size() == 5, "camera/distortion");
  try {
    validateIntrinsics(c, "camera/");
  } catch (const ConfigError& e) {
    throw ConfigError(e.what() + gazebo);
  }

  const bool depth_block = g && (g->type == "depth" || !g->depth_image_topic.empty());
  if (config.images.empty()) {
    spec.depth = depth_block;
  } else {
    const auto has = [&](const char* name) {
      return std::find(config.images.begin(), config.images.end(), name) != config.images.end();
    };
    spec.rgb = has("rgb");
    spec.depth = has("depth");
    spec.label = has("label");
  }
  spec.images_from = pick(!config.images.empty(), "camera/images");
  spec.format = g ? g->format : CameraFormat::kRgb8;

  if (config.noise_std >= 0.0) {
    spec.noise_std = config.noise_std;
  } else if (g) {
    spec.noise_mean = g->noise_mean;
    spec.noise_std = g->noise_stddev;
  }
  spec.noise_from = pick(config.noise_std >= 0.0, "camera/noise_std");
  if (!(spec.noise_std >= 0.0 && std::isfinite(spec.noise_std) && std::isfinite(spec.noise_mean))) {
    throwInvalid("camera/noise_std", spec.noise_std, "must be >= 0, finite" + gazebo);
  }

  // The plugin's <updateRate> is what its topics run at; else the sensor's <update_rate>.
  const double rate = !g                            ? 0.0
                      : g->plugin_update_rate > 0.0 ? g->plugin_update_rate
                                                    : g->update_rate;
  if (config.update_every > 0) {
    spec.update_every = config.update_every;
  } else if (rate > 0.0) {
    if (!std::isfinite(rate)) {
      throwInvalid("camera/update_every", rate, "the update rate must be finite" + gazebo);
    }
    spec.update_every = std::max(1, static_cast<int>(std::lround(1.0 / (rate * control_dt))));
  }
  spec.update_from = pick(config.update_every > 0, "camera/update_every");
  if (config.update_every == 0 && rate <= 0.0) spec.update_from = "default";

  // gazebo_ros_camera's and gazebo_ros_openni_kinect's names and defaults; gazebo_ros_multicamera
  // puts each camera under <cameraName>/left or /right (by its name), here any other under its
  // own name.
  std::string space = g && !g->camera_topic.empty() ? g->camera_topic : "camera";
  const std::string rig = g && g->type == "multicamera" ? multicameraSuffix(*g) : "";
  if (!rig.empty()) space = joinTopic(space, rig);
  const auto topic = [&](const std::string& given, const char* fallback) {
    return joinTopic(space, given.empty() ? fallback : given);
  };
  spec.image_topic = topic(g ? g->image_topic : "", "image_raw");
  spec.info_topic = topic(g ? g->info_topic : "", "camera_info");
  spec.depth_image_topic = topic(g ? g->depth_image_topic : "", "depth/image_raw");
  spec.depth_info_topic = topic(g ? g->depth_info_topic : "", "depth/camera_info");
  spec.label_topic = joinTopic(space, "label/image_raw");
  // A multicamera's cameras stand apart: each gets its own optical frame (Gazebo's plugin gives
  // all one frame and the right camera's baseline in P; here tf holds it).
  const bool named = g && !g->frame_name.empty();
  spec.frame = named ? g->frame_name : spec.link;
  if (!rig.empty()) spec.frame += "_" + rig;
  if (!named) spec.frame += "_optical_frame";
  if (spec.frame.front() == '/') spec.frame = spec.frame.substr(1);
  return spec;
}

}  // namespace

std::vector<CameraSpec> resolveCameras(const CameraConfig& config, const RobotModel& robot,
                                       double control_dt) {
  if (!config.enabled) return {};
  std::vector<const GazeboCamera*> blocks;
  for (const GazeboCamera& g : robot.gazebo().cameras) {
    if (config.link.empty() || g.link == config.link) blocks.push_back(&g);
  }
  if (blocks.empty() && !config.link.empty()) blocks.push_back(nullptr);  // parameters alone
  std::vector<CameraSpec> cameras;
  for (const GazeboCamera* g : blocks) cameras.push_back(resolveOne(config, robot, g, control_dt));
  // Two cameras on one topic would interleave their images: refused, naming both.
  const auto published = [](const CameraSpec& c) {
    std::vector<std::string> topics;
    if (c.rgb) topics.push_back(c.image_topic);
    if (c.depth) topics.push_back(c.depth_image_topic);
    if (c.label) topics.push_back(c.label_topic);
    return topics;
  };
  std::vector<std::vector<std::string>> topics;
  for (const CameraSpec& c : cameras) topics.push_back(published(c));
  for (std::size_t a = 0; a < cameras.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      for (const std::string& topic : topics[a]) {
        if (std::find(topics[b].begin(), topics[b].end(), topic) != topics[b].end()) {
          throw ConfigError("the cameras '" + cameras[b].name + "' and '" + cameras[a].name +
                            "' would both publish " + topic +
                            ": give their plugins different <cameraName>s");
        }
      }
    }
  }
  // The camera whose images the batch carries comes first.
  if (!config.batch_camera.empty()) {
    const auto found = std::find_if(cameras.begin(), cameras.end(), [&](const CameraSpec& c) {
      return c.name == config.batch_camera;
    });
    if (found == cameras.end()) {
      std::string names;
      for (const CameraSpec& c : cameras) names += (names.empty() ? "'" : ", '") + c.name + "'";
      throwInvalid("camera/batch_camera", "'" + config.batch_camera + "'",
                   "names no camera (the cameras: " + (names.empty() ? "none" : names) + ")");
    }
    std::rotate(cameras.begin(), found, found + 1);
  }
  return cameras;
}

std::string describeCamera(const CameraSpec& s) {
  std::ostringstream out;
  const CameraIntrinsics& c = s.intrinsics;
  out << "camera '" << s.name << "' on link '" << s.link << "' (" << s.link_from << "): " << c.width
      << " x " << c.height << " px (" << s.size_from << "), horizontal fov " << c.horizontal_fov
      << " rad (" << s.fov_from << "), clip [" << c.near << ", " << c.far << "] m (" << s.clip_from
      << "), distortion [" << c.k1 << ", " << c.k2 << ", " << c.k3 << ", " << c.p1 << ", " << c.p2
      << "] (" << s.distortion_from << "), images";
  for (const auto& [on, name] :
       {std::pair<bool, const char*>{s.rgb, " rgb"}, {s.depth, " depth"}, {s.label, " label"}}) {
    if (on) out << name;
  }
  out << " (" << s.images_from << "), noise mean " << s.noise_mean << " std " << s.noise_std << " ("
      << s.noise_from << "), every " << s.update_every << " control steps (" << s.update_from
      << "), frame '" << s.frame << "'";
  if (s.shadows) out << ", shadows";
  if (s.randomizesAppearance()) {
    out << ", appearance randomised (colours " << (s.random_colours ? "on" : "off")
        << ", light intensity " << (s.light_intensity.empty() ? "1" : listText(s.light_intensity))
        << ", light direction " << (s.random_light_direction ? "drawn" : "fixed") << ", exposure "
        << (s.exposure.empty() ? "1" : listText(s.exposure)) << ", pose jitter "
        << (s.pose_jitter.empty() ? "none" : listText(s.pose_jitter)) << ")";
  }
  return out.str();
}

}  // namespace jetbot_rl
