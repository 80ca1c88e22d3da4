#pragma once

// A camera on a link of the robot (docs/camera.md), rendered in each env's world. Its defaults
// are the robot description's Gazebo camera block (camera, depth or multicamera), where it has
// one; a parameter that is set wins, and a link without a block gets a camera from the parameters
// alone.

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// The `camera/...` parameters; 0, -1 and [] stand for the robot description's value.
struct CameraConfig {
  bool enabled = true;          ///< false: no camera, even when the robot description declares one.
  std::string link;             ///< Link of the cameras; empty: every Gazebo camera block's.
  std::string batch_camera;     ///< The camera whose images learners get; empty: the first.
  int width = 0;                ///< [px]; 0: the block's (without one: 64).
  int height = 0;               ///< [px]; 0: the block's (without one: 64).
  double horizontal_fov = 0.0;  ///< [rad]; 0: the block's (without one: 1.047).
  std::vector<double> clip;     ///< [near, far] [m]; []: the block's (without: [0.05, 10]).
  std::vector<double> distortion;   ///< [k1, k2, k3, p1, p2]; []: the block's (without: none).
  std::vector<std::string> images;  ///< rgb, depth, label; []: rgb (a depth block: rgb, depth).
  double noise_std = -1.0;    ///< Gaussian noise on [0, 1] intensities; -1: the block's (else 0).
  int update_every = 0;       ///< Control steps between images; 0: from the block's update rate.
  bool batch_images = true;   ///< The images go into every step's result for learners.
  bool robot_visuals = true;  ///< The robots are drawn by their URDF visuals.
  bool shadows = false;       ///< The light casts shadows.
  bool world_visuals = true;  ///< A Gazebo world is drawn by its <visual> elements.
  // Appearance randomisation: drawn per env at each reset from its own stream (off: nothing).
  bool random_colours = false;          ///< Surface colours and the floor image's tint.
  std::vector<double> light_intensity;  ///< [min, max] of the light's intensity; []: 1.
  bool random_light_direction = false;  ///< The light's azimuth and elevation.
  std::vector<double> exposure;         ///< [min, max] gain on intensities; []: 1.
  std::vector<double> pose_jitter;      ///< [position m, angle rad] of the camera; []: none.
};

template <typename C, typename V>
IfConfig<C, CameraConfig> visitFields(C& c, V&& v) {
  const Range<double> any{-1e4, 1e4, false, false, ""};
  v("camera/enabled", c.enabled, AnyValue{},
    "false: no camera, even when the robot description declares one.");
  v("camera/link", c.link, AnyValue{"", "empty: every Gazebo camera block's link"},
    "URDF link whose cameras are used (each looking along its x axis, z up: its block's <pose> "
    "on top); a link without a Gazebo camera block gets one camera made of these parameters; no "
    "link and no block: no camera. The parameters below set every camera's value.");
  v("camera/batch_camera", c.batch_camera, AnyValue{"", "empty: the first camera"},
    "The camera whose images go into every step for learners (camera/batch_images), by name: "
    "its Gazebo sensor's name, SENSOR/CAMERA for a camera of a multicamera, camera for one of "
    "the parameters alone; the others are published on ROS only.");
  v("camera/width", c.width, inRange(0, 4096, "px", "0: the block's, else 64"), "Image width.");
  v("camera/height", c.height, inRange(0, 4096, "px", "0: the block's, else 64"), "Image height.");
  v("camera/horizontal_fov", c.horizontal_fov,
    Range<double>{0.0, 3.141592653589793, false, true, "rad", "0: the block's, else 1.047"},
    "Horizontal field of view of the pinhole (focal length width / 2 / tan(fov / 2) px).");
  v("camera/clip", c.clip, EachValue<double>{any},
    "[near, far] [m], 0 < near < far: depth is measured between them (REP 118: -inf nearer, "
    "+inf farther); []: the block's <clip>, else [0.05, 10].");
  v("camera/distortion", c.distortion, EachValue<double>{any},
    "[k1, k2, k3, p1, p2] Brown-Conrady distortion (Gazebo's <distortion>); []: the block's, "
    "else none.");
  v("camera/images", c.images, NameList{"", true},
    "Images made at each update, of rgb (rgb8), depth (32FC1 [m] along the optical axis) and "
    "label (mono8 SurfaceClass); []: rgb, with depth for a depth or openni block.");
  v("camera/noise_std", c.noise_std, atLeast(-1.0, "", "-1: the block's, else 0"),
    "Gaussian noise added to every colour channel on [0, 1] intensities, clamped (Gazebo's "
    "camera noise; from the env's own camera stream).");
  v("camera/update_every", c.update_every, inRange(0, 100000, "control steps"),
    "Control steps between images; 0: from the block's update rate (the plugin's <updateRate> "
    "when set, else the sensor's <update_rate>: round(1 / (rate x control step)), at least 1), "
    "else every step.");
  v("camera/batch_images", c.batch_images, AnyValue{},
    "The images go into every step for learners (~env_step's images_* fields, the vec envs' "
    "observations, EnvSpec image_kinds); false: only into the robot view's image topics.");
  v("camera/robot_visuals", c.robot_visuals, AnyValue{},
    "The robots (the camera's own, without its camera link's visuals, and the others of its "
    "world) are drawn by their URDF <visual> shapes and material colours; false: none of its own, "
    "the others as the cylinders the scanner sees (for a robot whose visual meshes are not at "
    "hand).");
  v("camera/world_visuals", c.world_visuals, AnyValue{},
    "A Gazebo world (world/gazebo_world) is drawn by its models' <visual> shapes and material "
    "colours (read at start-up only with a camera); false: by the shapes the scanner sees, in "
    "the map colour.");
  v("camera/shadows", c.shadows, AnyValue{},
    "The directional light casts shadows: a surface it does not reach gets the ambient light "
    "alone (one more ray per lit pixel).");
  v("camera/random_colours", c.random_colours, AnyValue{},
    "Appearance randomisation: at each reset each env draws the colour of its ground, walls, "
    "map blocks, obstacles and movers (each channel uniform in [0.1, 0.9]) and a tint of the "
    "floor image (each channel uniform in [0.7, 1.3]).");
  v("camera/light_intensity", c.light_intensity, EachValue<double>{inRange(0.0, 10.0)},
    "[min, max]: at each reset each env draws its light's intensity uniformly in it; []: 1.");
  v("camera/random_light_direction", c.random_light_direction, AnyValue{},
    "At each reset each env draws where its light comes from: azimuth uniform in [-pi, pi), "
    "elevation uniform in [0.35, 1.4] rad above the horizon.");
  v("camera/exposure", c.exposure, EachValue<double>{inRange(0.0, 10.0)},
    "[min, max]: at each reset each env draws its camera's exposure (a gain on every "
    "intensity, clamped at 1) uniformly in it; []: 1.");
  v("camera/pose_jitter", c.pose_jitter, EachValue<double>{inRange(0.0, 1.0)},
    "[position m, angle rad]: at each reset each env moves its camera by up to +-position along "
    "each axis and turns it by up to +-angle about each axis of its body frame (uniform); []: "
    "none.");
}

/// The rules of CameraConfig's fields: clip has 0 or 2 values, distortion 0 or 5, images only
/// rgb, depth and label, noise_std -1 or >= 0, light_intensity and exposure [min, max] with
/// min <= max, pose_jitter 0 or 2 values.
void checkFieldRules(const CameraConfig& config);

}  // namespace jetbot_rl
