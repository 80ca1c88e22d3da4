#pragma once

#include <actionlib/server/action_server.h>
#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/ros/deploy/map_input.h"

namespace jetbot_rl {

/**
 * Goals for a task with one (navigation), as move_base takes them: the `move_base` action
 * (move_base_msgs/MoveBaseAction through actionlib, a new goal preempting the current one, cancel
 * stopping it) and PoseStamped goals as RViz's "2D Nav Goal" publishes them on
 * /move_base_simple/goal, each sent on as a new action goal as move_base does. A goal is
 * transformed into the odometry frame with the MapInput's tf2 and, with a map, into the map's
 * frame (its header's) and checked against its free cells there; a goal that fails is ABORTED at
 * once ("refused: why"). What became of each goal (accepted, reached, refused: ..., no path: ...,
 * aborted: ..., canceled, preempted) is also published as a std_msgs/String, and the goal being
 * pursued on ~current_goal (as move_base does; a PoseStamped with an empty frame_id follows when
 * the goal ends) and as an arrow on ~current_goal_marker, deleted when the goal ends (RViz's Pose
 * display keeps the last pose it could place; a Marker display takes a DELETE off the screen). A
 * goal whose client disconnects (its node exits or dies: its connections to the action's topics
 * close) is ABORTED and the robot stops.
 */
class MoveBaseServer {
 public:
  /// The odometry frame, or "" before any odometry came.
  using OdomFrame = std::function<std::string()>;

  /// `p.goal_topic` and `p.outcome_topic` may be private ("~name"); `p.action_name` is resolved
  /// in `nh`'s namespace. `map` (borrowed: it must outlive the server) checks goals. `accepted`
  /// is called for each new goal (a new episode starts), `canceled` when a goal is canceled (the
  /// robot stops at once).
  MoveBaseServer(ros::NodeHandle& nh, ros::NodeHandle& pnh, const MoveBaseServerParams& p,
                 const MapInput& map, OdomFrame odom_frame, std::function<void()> accepted,
                 std::function<void()> canceled);
  ~MoveBaseServer();
  MoveBaseServer(const MoveBaseServer&) = delete;
  MoveBaseServer& operator=(const MoveBaseServer&) = delete;

  /// The current goal in the odometry frame, or none (no goal yet, ended).
  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }
  /// Its heading in the odometry frame [rad].
  double goalYaw() const { return goal_yaw_; }
  /// The current goal in the map's frame (with a map).
  const std::optional<Eigen::Vector2d>& goalInMap() const { return goal_in_map_; }
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
  /// The simple goals' topic.
  std::string topic() const { return goal_sub_.getTopic(); }
  /// The action's namespace (e.g. /move_base).
  const std::string& actionName() const { return action_name_; }

 private:
  using Server = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
  void onSimpleGoal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onActionGoal(Server::GoalHandle handle);
  void onCancel(Server::GoalHandle handle);
  /// Validates the current goal's target and takes it, or aborts it ("refused: why").
  void take(const geometry_msgs::PoseStamped& target);
  /// Forgets the current goal; one shown on ~current_goal and ~current_goal_marker is cleared
  /// there.
  void clear();
  void report(const std::string& outcome);
  /// `msg` in `frame` (x, y, yaw), or false with `why`.
  bool transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                 Eigen::Vector2d& out, double& yaw, std::string& why) const;

  const MapInput& map_;
  OdomFrame odom_frame_;
  std::function<void()> accepted_, canceled_;
  std::string action_name_;
  std::unique_ptr<Server> server_;
  std::optional<Server::GoalHandle> active_;  // the goal pursued
  std::string client_;  // the node that sent it, while connected to the action; "": none
  ros::Publisher outcome_pub_, action_goal_pub_, current_goal_pub_, goal_marker_pub_;
  ros::Subscriber goal_sub_;
  bool started_ = false;
  std::optional<Eigen::Vector2d> goal_, goal_in_map_;
  double goal_yaw_ = 0.0;
  std::string shown_frame_;  // the frame of the goal shown on ~current_goal_marker
};

}  // namespace jetbot_rl
