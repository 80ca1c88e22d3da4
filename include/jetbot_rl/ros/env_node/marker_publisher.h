#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <visualization_msgs/MarkerArray.h>

#include "jetbot_rl/ros/env_node/state_output.h"
#include "jetbot_rl/tasks/task_capabilities.h"

namespace jetbot_rl {

/**
 * visualization_msgs/MarkerArray on ~markers (latched, frame `world`) for the first `envs` envs:
 * the chassis as a box, an arrow along the robot's forward direction and one per direction the
 * task draws (Task::arrowNames: the command task's command, the walkthrough's second arrow);
 * coloured per env; with a world, its walls and the obstacles of each env's current layout (grey
 * boxes and cylinders; an obstacle left out of the episode is hidden). Sent at most `rate` Hz of
 * simulation time (with the tf batches). When disabled, and at finish() (the node's end), it
 * publishes DELETEALL so that RViz drops stale markers.
 */
class EnvMarkerPublisher : public StateOutput {
 public:
  /// `envs`: envs with markers (clamped to the batch); `enabled`: the `markers` parameter;
  /// ~markers' queue kept in `queues`.
  EnvMarkerPublisher(ros::NodeHandle& pnh, const BatchedEnv& env, int envs, double rate,
                     bool enabled, CountedSubscriberQueues& queues);
  EnvMarkerPublisher(const EnvMarkerPublisher&) = delete;
  EnvMarkerPublisher& operator=(const EnvMarkerPublisher&) = delete;

  void capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) override;
  void send() override;
  void finish() override;

 private:
  void deleteAll();

  ros::Publisher pub_;
  int envs_;
  bool enabled_;
  const ArrowDrawing* arrow_task_;  // the task, when it draws arrows
  int arrows_;                      // the task's arrows per env
  SimRateGate gate_;
  bool due_ = false;
  visualization_msgs::MarkerArray array_;  // reused: names, colours and scales are set once
  Eigen::Isometry3d body_offset_;          // chassis box in the root link frame
};

}  // namespace jetbot_rl
