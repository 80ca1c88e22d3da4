#pragma once

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// jetbot_depth_scan's parameters: where the depth images come from, the frames, and the scan
/// made of them (as scan/source camera_depth makes it in training).
struct DepthScanParams {
  std::string checkpoint;  ///< A camera-depth navigator: its range and heights; "": none.
  std::string depth_topic = "camera/depth/image_raw";  ///< sensor_msgs/Image, 32FC1 or 16UC1.
  std::string image_transport = "raw";                 ///< The transport its images come by.
  std::string scan_topic = "scan";                     ///< sensor_msgs/LaserScan published.
  std::string base_frame = "base_link";                ///< The robot's root link: the scan's frame.
  std::string ground_frame = "base_footprint";         ///< A frame whose z = 0 is the ground.
  int samples = 0;                                     ///< Scan samples; 0: one per image column.
  std::vector<double> angles;  ///< [min, max] bearings [rad]; []: the camera's field of view.
  std::vector<double> range{0.12, 3.5};  ///< [min, max] ranges [m].
  double min_height = 0.03;              ///< Points below this above the ground are the floor [m].
  double max_height = 0.5;               ///< Points above this pass over the robot [m].
  double transform_timeout = 0.2;        ///< How long to wait for tf at an image's time [s, wall].
};

template <typename C, typename V>
IfConfig<C, DepthScanParams> visitFields(C& c, V&& v) {
  v("checkpoint", c.checkpoint, AnyValue{"", "empty: none"},
    "A checkpoint (or run directory: its checkpoints/best.pt) trained on a depth camera's scan "
    "(scan_source camera_depth): range, min_height and max_height are its scan_range and "
    "scan_heights, and one given anyway overrides it with a warning naming both.");
  v("depth_topic", c.depth_topic, AnyValue{},
    "The depth camera's sensor_msgs/Image (32FC1 in metres or 16UC1 in millimetres, REP 118), "
    "its CameraInfo beside it (camera_info in the same namespace), through image_transport.");
  v("image_transport", c.image_transport, AnyValue{},
    "The image_transport the depth images come by (raw; compressedDepth where installed).");
  v("scan_topic", c.scan_topic, AnyValue{}, "The sensor_msgs/LaserScan published, one per image.");
  v("base_frame", c.base_frame, AnyValue{},
    "The robot's root link: the scan's frame, its bearings about its origin and heading (as "
    "training's scan lies about the root link).");
  v("ground_frame", c.ground_frame, AnyValue{},
    "A frame whose z = 0 is the ground (REP 120's base_footprint; in the simulator, odom): "
    "heights are measured from it.");
  v("samples", c.samples, inRange(0, 100000, "", "0: the image's width"),
    "Scan samples over angles: a point counts for the sample nearest its bearing. 0: one per "
    "image column (training's default).");
  v("angles", c.angles, AnyValue{"rad", "[]: the camera's field of view"},
    "[min, max] bearings of the first and last sample. []: +- half the camera's horizontal field "
    "of view (atan(width / 2 fx)), as training's default.");
  v("range", c.range, intervalOf(inRange(0.0, 1000.0, "m")),
    "[min, max]: nearer than min is -inf (too close), beyond max no point (+inf), REP 117.");
  v("min_height", c.min_height, inRange(-10.0, 10.0, "m"),
    "Points lower than this above the ground are the floor, never an obstacle (scan/min_height).");
  v("max_height", c.max_height, inRange(-10.0, 10.0, "m"),
    "Points higher than this pass over the robot (scan/max_height).");
  v("transform_timeout", c.transform_timeout, positiveUpTo(10.0, "s, wall"),
    "How long an image waits for tf to hold its camera's pose at its time; then it is refused "
    "(counted and warned of).");
}

/// angles empty or [min, max] with min < max; min_height below max_height; range's min < max.
void checkFieldRules(const DepthScanParams& params);

}  // namespace jetbot_rl
