#pragma once

// A scan from a camera's depth image (scan/source camera_depth): what pointcloud_to_laserscan
// does with a depth camera's points, so that a policy that observes scan beams can see through
// the Jetbot's camera alone (its forward field of view).

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/sensors/camera_model.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/sensors/scanner_config.h"

namespace jetbot_rl {

/// The scan `config` (scan/source camera_depth) makes from `camera`'s depth image: in the robot's
/// root link frame (its link; beams in the ground's plane about the link's origin, angle 0 along
/// its heading); by default a sample per image column over the camera's horizontal field of view,
/// the camera's cadence, range [0.12, min(far clip, 3.5)] m; no noise of its own (the depth's).
/// ConfigError naming the field: a camera without depth images (camera/images), scan/link given,
/// min_height >= max_height, angles or range as resolveScanner() refuses them.
ScannerSpec resolveDepthScanner(const ScannerConfig& config, const RobotModel& robot,
                                const CameraSpec& camera);

/// The scan `config` gives: a laser's (resolveScanner()), or with scan/source camera_depth one
/// from the first of `cameras` (the batch's; resolveDepthScanner()); ConfigError naming
/// scan/source for camera_depth without a camera.
std::optional<ScannerSpec> resolveScan(const ScannerConfig& config, const RobotModel& robot,
                                       const std::vector<CameraSpec>& cameras, double control_dt);

/**
 * Reduces one depth image to a scan: each pixel's point (its ray x its depth along the optical
 * axis, from `optical`: the optical frame in the env frame when it was made) between
 * spec.min_height and spec.max_height above the ground (z = 0) counts for the sample nearest its
 * bearing from `origin` (the robot's root link in the env frame, its heading taken about z), the
 * nearest one wins. Writes spec.samples ranges to `ranges` (REP 117): +inf (kNoReturn) where no
 * point lies within range_max, -inf (kTooClose) nearer than range_min. Depth out of range (+-inf,
 * NaN) is no point.
 */
void depthToScan(const ScannerSpec& spec, const CameraModel& model, const float* depth,
                 const Eigen::Isometry3d& optical, const Eigen::Isometry3d& origin, float* ranges);
/// depthToScan() through the given pixel rays (row by row, z = 1): a robot's depth camera as its
/// CameraInfo describes it (pinholeRays()).
void depthToScan(const ScannerSpec& spec, const std::vector<Eigen::Vector3f>& rays,
                 const float* depth, const Eigen::Isometry3d& optical,
                 const Eigen::Isometry3d& origin, float* ranges);

/// The ray (z = 1) through each pixel centre, row by row, of a `width` x `height` camera as a ROS
/// CameraInfo describes it: K's fx, fy, cx, cy [px] and plumb_bob's D (k1, k2, p1, p2, k3; empty:
/// none), undone as CameraModel undoes it. For the simulated camera's own CameraInfo, its
/// CameraModel::pixelRays() bit for bit. ConfigError naming K, D or camera_info/... otherwise.
std::vector<Eigen::Vector3f> pinholeRays(int width, int height, double fx, double fy, double cx,
                                         double cy, const std::vector<double>& plumb_bob);

}  // namespace jetbot_rl
