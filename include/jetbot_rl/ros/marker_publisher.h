#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <visualization_msgs/MarkerArray.h>

#include "jetbot_rl/batched_env.h"

namespace jetbot_rl {

/**
 * visualization_msgs/MarkerArray on ~markers (latched, frame `world`) for the first `envs` envs:
 * the chassis as a box, an arrow along the robot's forward direction and, for the command task, an
 * arrow along its command (the walkthrough's two arrows); coloured per env. When disabled, and
 * when the node ends, it publishes DELETEALL so that RViz drops stale markers.
 */
class EnvMarkerPublisher {
 public:
  /// `envs`: envs with markers (clamped to the batch); `enabled`: the `markers` parameter.
  EnvMarkerPublisher(ros::NodeHandle& pnh, const BatchedEnv& env, int envs, bool enabled);
  ~EnvMarkerPublisher();
  EnvMarkerPublisher(const EnvMarkerPublisher&) = delete;
  EnvMarkerPublisher& operator=(const EnvMarkerPublisher&) = delete;

  /// Publishes the markers of the current state, stamped `stamp` (simulation time).
  void publish(const BatchedEnv& env, const ros::Time& stamp);

 private:
  void deleteAll();

  ros::Publisher pub_;
  int envs_;
  bool enabled_;
  visualization_msgs::MarkerArray array_;  // reused: names, colours and scales are set once
  Eigen::Isometry3d body_offset_;          // chassis box in the root link frame
};

}  // namespace jetbot_rl
