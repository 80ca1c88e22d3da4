#pragma once

// The Jetbot notebooks' data sets from simulated, randomised worlds (jetbot_rl_dataset): the
// collision avoidance notebook's dataset/blocked and dataset/free images, and the road following
// notebook's images named by their steering target, so that a user trains the notebooks' ResNet-18
// on them.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

class BatchedEnv;
class CameraModel;

/// Which notebook's data set.
enum class DatasetKind { kCollisionAvoidance, kRoadFollowing };

inline const EnumNameList<DatasetKind>& enumNames(DatasetKind) {
  static const EnumNameList<DatasetKind> names{
      {DatasetKind::kCollisionAvoidance, "collision_avoidance"},
      {DatasetKind::kRoadFollowing, "road_following"}};
  return names;
}

/// What jetbot_rl_dataset writes.
struct DatasetOptions {
  DatasetKind kind = DatasetKind::kCollisionAvoidance;
  std::string out;                ///< The data set's folder (made when missing).
  int count = 100;                ///< Images; collision avoidance: half blocked, half free.
  double blocked_distance = 0.3;  ///< An obstacle this close ahead makes an image blocked [m].
  double lookahead = 0.4;         ///< The steering target this far along the centreline [m].
  std::uint64_t seed = 0;         ///< The first reset's seed (each reset the next).
  int quality = 90;               ///< JPEG quality, 1-100.
};

/// What was written.
struct DatasetSummary {
  int blocked = 0, free = 0;  ///< Collision avoidance images.
  int road = 0;               ///< Road following images.
  int resets = 0;             ///< Resets of the batch drawn.
};

/// True when something (a wall, the map, an obstacle, a person) that env `row`'s camera (of
/// projection `camera`: the batch camera's, built once) sees lies within `distance` [m] ahead of
/// its robot and `half_width` [m] of its heading line: what the collision avoidance notebook
/// calls blocked. Needs depth and label images (InputError).
bool blockedAhead(const BatchedEnv& env, const CameraModel& camera, int row, double distance,
                  double half_width);

/// Where in env `row`'s image [px] (of projection `camera`) the point `lookahead` [m] along its
/// track's centreline lies (the road following notebook's target), or none outside the image.
/// Needs the road following task (InputError).
std::optional<Eigen::Vector2d> roadTarget(const BatchedEnv& env, const CameraModel& camera, int row,
                                          double lookahead);

/// Writes the data set of `options` from `env`'s resets (rgb images of its batch camera as
/// JPEG): collision avoidance into out/blocked and out/free until each holds count / 2, road
/// following as out/xy_<x>_<y>_<n>.jpg (the notebook's names: the target's pixel). Error naming
/// the file it cannot write, ConfigError when the env cannot make them (no camera, the images or
/// the task missing), Error when 1000 resets per image do not balance the classes.
DatasetSummary writeNotebookDataset(BatchedEnv& env, const DatasetOptions& options);

}  // namespace jetbot_rl
