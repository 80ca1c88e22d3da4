#pragma once

// A saved world's <state> (Gazebo's File > Save World writes one), applied as Gazebo 11 applies it
// when it loads the world (World::Load, then World::SetState with the first <state>): the models
// of its <insertions> added, every model and link it names put at its world pose (a link it does
// not name moves with its model), the models of its <deletions> removed.

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

namespace jetbot_rl {

/// The poses of a world's first <state>, all in the world frame.
struct SavedState {
  std::map<std::string, Eigen::Isometry3d> models;  ///< "model" or "outer::inner" -> its pose.
  std::map<std::string, Eigen::Isometry3d> links;   ///< "model::link" -> its pose.
  /// "FILE:LINE: model 'NAME'" of each model whose <scale> is not 1 1 1 (not applied: a WARN).
  std::vector<std::string> scaled;
};

/**
 * Applies the first <state> of `world` (the <world> element of the file at `path`) to it: the
 * models of its <insertions> appended to the world (they get no pose from the state otherwise),
 * the top-level models and includes its <deletions> name removed, the <state> itself removed;
 * returns its poses. True in `changed` when the world's models changed. ConfigError naming the
 * file and line for a pose that is not six numbers.
 */
SavedState takeSavedState(tinyxml2::XMLElement& world, const std::string& path, bool& changed);

}  // namespace jetbot_rl
