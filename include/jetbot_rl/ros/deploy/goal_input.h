#pragma once

#include <actionlib/server/action_server.h>
#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "jetbot_rl/world/occupancy_map.h"

namespace jetbot_rl {

/// The grid of an OccupancyGrid message as the core's OccupancyMap (cells, resolution, origin).
OccupancyMap occupancyMapOf(const nav_msgs::OccupancyGrid& grid);

/**
 * Goals for a task with one (navigation), as move_base takes them: the `move_base` action
 * (move_base_msgs/MoveBaseAction through actionlib, a new goal preempting the current one, cancel
 * stopping it) and PoseStamped goals as RViz's "2D Nav Goal" publishes them on
 * /move_base_simple/goal, each sent on as a new action goal as move_base does. A goal is
 * transformed into the odometry frame with tf2 and, with a map, into the map's frame (its
 * header's) and checked against its free cells there; a goal that fails is ABORTED at once
 * ("refused: why"). What became of each goal (accepted, reached, refused: ..., no path: ...,
 * aborted: ..., canceled, preempted) is also published as a std_msgs/String, and the goal being
 * pursued on ~current_goal (as move_base does; RViz shows it). A goal whose client disconnects
 * (its node exits or dies: its connections to the action's topics close) is ABORTED and the robot
 * stops.
 */
class GoalInput {
 public:
  /// The odometry frame, or "" before any odometry came.
  using OdomFrame = std::function<std::string()>;

  /// `goal_topic` and `outcome_topic` may be private ("~name"); `action_name` is resolved in
  /// `nh`'s namespace; `map_topic` "" checks no map. `accepted` is called for each new goal (a
  /// new episode starts), `canceled` when a goal is canceled (the robot stops at once).
  GoalInput(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& action_name,
            const std::string& goal_topic, const std::string& outcome_topic,
            const std::string& map_topic, OdomFrame odom_frame, std::function<void()> accepted,
            std::function<void()> canceled);
  ~GoalInput();

  /// The current goal in the odometry frame, or none (no goal yet, ended).
  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }
  /// Its heading in the odometry frame [rad].
  double goalYaw() const { return goal_yaw_; }
  /// The current goal in the map's frame (with a map).
  const std::optional<Eigen::Vector2d>& goalInMap() const { return goal_in_map_; }
  /// `q` (the map's frame) in `frame` through tf's latest transform, or none without one.
  std::optional<Eigen::Vector2d> fromMap(const Eigen::Vector2d& q, const std::string& frame) const;
  /// The last valid map on the map topic, if any came, its frame, and how many came.
  const std::optional<OccupancyMap>& map() const { return map_; }
  const std::string& mapFrame() const { return map_frame_; }
  int mapsReceived() const { return maps_received_; }
  /// The tf2 buffer goals are transformed with.
  const tf2_ros::Buffer& tf() const { return tf_buffer_; }
  /// Starts the action server (once): when the robot's inputs (and the map, with one) are there,
  /// as move_base starts it once its costmaps are; a client's wait_for_server() waits for it.
  void start();
  bool started() const { return started_; }
  /// Ends the current goal SUCCEEDED (outcome "reached").
  void succeed();
  /// Ends the current goal ABORTED with `why` as its status text and outcome.
  void abort(const std::string& why);
  /// True (with `why`) when the node that sent the current goal has disconnected from the
  /// action: nothing could cancel the goal any more.
  bool clientGone(std::string& why) const;
  /// Publishes the action's feedback: the robot's pose from `odom`.
  void feedback(const nav_msgs::Odometry& odom);
  std::string topic() const { return goal_sub_.getTopic(); }
  /// The action's namespace (e.g. /move_base).
  const std::string& actionName() const { return action_name_; }

 private:
  void onSimpleGoal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  using Server = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
  void onActionGoal(Server::GoalHandle handle);
  void onCancel(Server::GoalHandle handle);
  /// Validates the current goal's target and takes it, or aborts it ("refused: why").
  void take(const geometry_msgs::PoseStamped& target);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void clear();
  void report(const std::string& outcome);
  /// True when `goal` (the map's frame) lies on a free cell of the map, or no map is given.
  bool onFreeCell(const Eigen::Vector2d& goal, std::string& why) const;
  /// `msg` in `frame` (x, y, yaw), or false with `why`.
  bool transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                 Eigen::Vector2d& out, double& yaw, std::string& why) const;

  OdomFrame odom_frame_;
  std::function<void()> accepted_, canceled_;
  std::string action_name_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  std::unique_ptr<Server> server_;
  std::optional<Server::GoalHandle> active_;  // the goal pursued
  std::string client_;  // the node that sent it, while connected to the action; "": none
  ros::Publisher outcome_pub_, action_goal_pub_, current_goal_pub_;
  ros::Subscriber goal_sub_, map_sub_;
  std::optional<OccupancyMap> map_;
  std::string map_frame_;
  int maps_received_ = 0;
  bool started_ = false;
  std::optional<Eigen::Vector2d> goal_, goal_in_map_;
  double goal_yaw_ = 0.0;
};

}  // namespace jetbot_rl
