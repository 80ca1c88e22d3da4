#pragma once

#include "jetbot_rl/eval/episode_loop.h"
#include "jetbot_rl/planning/dwa_planner.h"
#include "jetbot_rl/planning/path_tracker.h"

namespace jetbot_rl {

class NavigationTask;

/**
 * The dynamic window approach (DwaPlanner) driving every env of a navigation batch, as move_base
 * drives a robot with dwa_local_planner: each control step, each env's pose and body speeds, its
 * scan's returns as obstacles and the task's global path to its goal (nav/path; without it the
 * straight line; the local goal along it from where a PathTracker follows the robot) give a twist.
 * ConfigError unless the batch has the navigation task, a laser scanner and twist actions
 * (action_space twist).
 */
class DwaActor : public EpisodeActor {
 public:
  DwaActor(const BatchedEnv& env, const DwaConfig& config);
  void act(const BatchedEnv& env, std::vector<float>& actions) override;
  /// The new episodes' paths followed from their starts.
  void episodesBegan(const std::vector<std::uint32_t>& ids) override;

 private:
  const NavigationTask& task_;
  DwaPlanner planner_;
  std::vector<PathTracker> trackers_;  // per env: where it is along its path (the local goal)
};

}  // namespace jetbot_rl
