#pragma once

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/**
 * The observation contract: what a policy's observation is made of beyond its names, so that a
 * robot elsewhere builds the observer the policy was trained with (makeObserver(), task_factory.h)
 * and drives the way training did, from the checkpoint alone. Nested in BatchSpec (EnvSpec.msg and
 * the checkpoint carry it); each task writes its part (Task::describeObservation), the env the
 * scanner's range and the robot's geometry. A sensor joins with its own terms (a camera: its
 * image size, field of view and pose), 0 or empty where the task does not observe it.
 */
struct ObserverSpec {
  /// The scan beams observed, in the scanner's frame, in observation order [rad]; empty: no scan.
  std::vector<double> scan_beam_angles;
  double scan_beam_width = 0.0;    ///< Each beam's sector [rad]; 0: the nearest sample.
  std::vector<double> scan_range;  ///< [range_min, range_max] beams are clamped into [m].
  bool log_beams = false;          ///< Beams on a log scale of range (nav/log_beams).
  /// Where the scan came from: empty, a laser scanner; camera_depth, the camera's depth image.
  std::string scan_source;
  /// camera_depth: the points' [min, max] height above the ground [m]; empty: a laser's.
  std::vector<double> scan_heights;
  double goal_radius = 0.0;          ///< A goal is reached within this [m]; 0: no goal.
  double path_lookahead = 0.0;       ///< A global path's observed point along it [m]; 0: no path.
  double path_clearance = 0.0;       ///< Paths keep this beyond the footprint where there is room.
  double path_clearance_cost = 0.0;  ///< A cell at the footprint's cost beyond its length.
  double wheel_radius = 0.0;         ///< The cmd_vel kinematics [m]; 0: no differential drive.
  double wheel_separation = 0.0;     ///< The cmd_vel kinematics [m]; 0: no differential drive.
  double footprint_radius = 0.0;     ///< The robot's footprint, paths are planned for [m].
  /// The speed limit's path ahead in the scanner's frame: [front x, left y, right y] [m]; empty:
  /// no limit (speed_limit/enabled false).
  std::vector<double> speed_limit_path;
  /// The speed limit's [stop_distance, slow_distance] from the front [m]; empty: no limit.
  std::vector<double> speed_limit_distances;
  /// The camera image the policy observes beside the vector (rgb); empty: none.
  std::string camera_image;
  int camera_width = 0, camera_height = 0;  ///< Its size [px]; 0 without camera_image.
  double camera_hfov = 0.0;                 ///< Its horizontal field of view [rad]; 0 without.
};

/// The fields that make the observation itself (a policy is bound to them, as to its names).
template <typename C, typename V>
IfConfig<C, ObserverSpec> visitObservationFields(C& c, V&& v) {
  v("scan_beam_angles", c.scan_beam_angles, AnyValue{"rad"},
    "The scan beams the observation holds, in the scanner's frame (empty: no scan observed).");
  v("scan_range", c.scan_range, AnyValue{"m"},
    "The scanner's [range_min, range_max] the beams are clamped into and divided by the max of.");
  v("scan_beam_width", c.scan_beam_width, AnyValue{"rad"},
    "Each beam's sector: the beam is the smallest reading in [angle, angle + width); 0: the "
    "sample nearest to its angle.");
  v("log_beams", c.log_beams, AnyValue{},
    "The beams are observed on a log scale of range (nav/log_beams), not as range / range_max.");
  v("scan_source", c.scan_source, AnyValue{},
    "Where the scan beams came from in training: empty, a planar laser scanner (a LaserScan); "
    "camera_depth, the camera's depth image reduced to a scan (scan/source; on a robot: a "
    "LaserScan from its depth camera's points between scan_heights, as jetbot_depth_scan makes "
    "it).");
  v("scan_heights", c.scan_heights, AnyValue{"m"},
    "camera_depth: [min, max] height above the ground of the points the scan was made of; "
    "empty for a laser.");
  v("path_lookahead", c.path_lookahead, AnyValue{"m"},
    "A task that observes a global path (nav/path): the observed point's distance along it past "
    "the robot (nav/path_lookahead); 0: no path observed.");
  v("camera_image", c.camera_image, AnyValue{},
    "The camera image the policy observes beside the vector: rgb (the batch's images_rgb), or "
    "empty: none.");
  v("camera_width", c.camera_width, AnyValue{"px"}, "Its width; 0 without camera_image.");
  v("camera_height", c.camera_height, AnyValue{"px"}, "Its height; 0 without camera_image.");
  v("camera_hfov", c.camera_hfov, AnyValue{"rad"},
    "Its horizontal field of view (a robot's camera is resized to the policy's image, not "
    "cropped: its field of view should be this); 0 without camera_image.");
}

/// The fields of how goals end and of the robot the policy was trained on (a robot elsewhere
/// takes them unless its parameters say otherwise).
template <typename C, typename V>
IfConfig<C, ObserverSpec> visitGoalAndRobotFields(C& c, V&& v) {
  v("goal_radius", c.goal_radius, AnyValue{"m"},
    "A task with goals: a goal is reached within this of the root link origin (nav/goal_radius); "
    "0: no goal.");
  v("path_clearance", c.path_clearance, AnyValue{"m"},
    "A task that follows a path: the clearance beyond the footprint its paths keep where there "
    "is room (nav/path_clearance).");
  v("path_clearance_cost", c.path_clearance_cost, AnyValue{},
    "A task that follows a path: what a cell at the footprint costs beyond its length, per cell "
    "length (nav/path_clearance_cost).");
  v("wheel_radius", c.wheel_radius, AnyValue{"m"},
    "The cmd_vel kinematics' wheel radius; 0: the robot is no differential drive.");
  v("wheel_separation", c.wheel_separation, AnyValue{"m"},
    "The cmd_vel kinematics' wheel separation; 0: the robot is no differential drive.");
  v("footprint_radius", c.footprint_radius, AnyValue{"m"},
    "The robot's footprint radius (its collision shapes' extent about the root link origin), "
    "which paths are planned for.");
  v("speed_limit_path", c.speed_limit_path, AnyValue{"m"},
    "The forward speed limit the policy was trained behind (speed_limit/...): the robot's path "
    "ahead in the scanner's frame, [x of its front, y of its left side, y of its right side] "
    "(its collision shapes plus speed_limit/margin); empty: none.");
  v("speed_limit_distances", c.speed_limit_distances, AnyValue{"m"},
    "[stop_distance, slow_distance] of that limit, from the front: forward v 0 with a scan "
    "reading in the path this close, the action's bound with none within the second; empty: "
    "none.");
}

/// Every field: the observation's, then the goals' and the robot's.
template <typename C, typename V>
IfConfig<C, ObserverSpec> visitFields(C& c, V&& v) {
  visitObservationFields(c, v);
  visitGoalAndRobotFields(c, v);
}

/// scan_range is [range_min, range_max] with 0 <= min < max when there are beams, else empty;
/// ConfigError naming the field and its value.
void checkFieldRules(const ObserverSpec& spec);

}  // namespace jetbot_rl
