#include "jetbot_rl/ros/deploy/move_base_server.h"

#include <move_base_msgs/MoveBaseActionGoal.h>
#include <ros/console.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/Marker.h>

#include <cmath>

#include "jetbot_rl/ros/common/peer_links.h"
#include "jetbot_rl/ros/common/private_topic.h"

namespace jetbot_rl {
namespace {

/// The goal's arrow for RViz (`action` ADD at `goal`, or DELETE): a Marker display takes a
/// DELETE off the screen, where a Pose display keeps the last pose it could place.
visualization_msgs::Marker goalMarker(const geometry_msgs::PoseStamped& goal, int action) {
  visualization_msgs::Marker m;
  m.header.frame_id = goal.header.frame_id;  // stamp 0: tf's latest, as for a latched goal
  m.ns = "goal";
  m.id = 0;
  m.type = visualization_msgs::Marker::ARROW;
  m.action = action;
  m.pose = goal.pose;
  m.scale.x = 0.4;  // [m] length
  m.scale.y = m.scale.z = 0.08;
  m.color.r = 1.0f;
  m.color.g = 0.67f;
  m.color.a = 1.0f;
  return m;
}

bool finitePose(const geometry_msgs::Pose& p) {
  for (double x : {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y,
                   p.orientation.z, p.orientation.w}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

}  // namespace

MoveBaseServer::MoveBaseServer(ros::NodeHandle& nh, ros::NodeHandle& pnh,
                               const MoveBaseServerParams& p, const MapInput& map,
                               OdomFrame odom_frame, std::function<void()> accepted,
                               std::function<void()> canceled)
    : map_(map),
      odom_frame_(std::move(odom_frame)),
      accepted_(std::move(accepted)),
      canceled_(std::move(canceled)),
      action_name_(nh.resolveName(p.action_name)) {
  outcome_pub_ = nh.advertise<std_msgs::String>(resolvePrivateTopic(pnh, p.outcome_topic), 10);
  // actionlib's ActionServer rather than its SimpleActionServer: the goal's id names its client.
  server_ = std::make_unique<Server>(
      nh, action_name_, [this](Server::GoalHandle h) { onActionGoal(h); },
      [this](Server::GoalHandle h) { onCancel(h); }, false);
  // A simple goal becomes an action goal on the server's own goal topic, as move_base sends it.
  action_goal_pub_ = nh.advertise<move_base_msgs::MoveBaseActionGoal>(action_name_ + "/goal", 1);
  current_goal_pub_ = pnh.advertise<geometry_msgs::PoseStamped>("current_goal", 1, true);
  goal_marker_pub_ = pnh.advertise<visualization_msgs::Marker>("current_goal_marker", 1, true);
  goal_sub_ =
      nh.subscribe(resolvePrivateTopic(pnh, p.goal_topic), 10, &MoveBaseServer::onSimpleGoal, this);
}

MoveBaseServer::~MoveBaseServer() {
  if (active_) active_->setAborted(move_base_msgs::MoveBaseResult(), "shut down");
}

void MoveBaseServer::start() {
  if (started_) return;
  server_->start();
  started_ = true;
  ROS_INFO("the move_base action %s takes goals", action_name_.c_str());
}

void MoveBaseServer::clear() {
  if (goal_) {
    // move_base's topic gets a pose without a frame in the ended goal's place; RViz's Pose
    // display keeps drawing the last pose it could place, so the arrow is a Marker, deleted.
    geometry_msgs::PoseStamped none;
    none.header.stamp = ros::Time::now();
    current_goal_pub_.publish(none);
    none.header.frame_id = shown_frame_;  // RViz's tf filter passes a DELETE in a known frame
    goal_marker_pub_.publish(goalMarker(none, visualization_msgs::Marker::DELETE));
  }
  goal_.reset();
  goal_in_map_.reset();
  active_.reset();
  client_.clear();
}

void MoveBaseServer::succeed() {
  if (active_) active_->setSucceeded(move_base_msgs::MoveBaseResult(), "reached");
  clear();
  report("reached");
}

void MoveBaseServer::abort(const std::string& why) {
  ROS_WARN("goal ended: %s; the robot stops", why.c_str());
  if (active_) active_->setAborted(move_base_msgs::MoveBaseResult(), why);
  clear();
  report(why);
}

bool MoveBaseServer::clientGone(std::string& why) const {
  if (client_.empty()) return false;
  // A client subscribes to the action's status, feedback and result: gone from all three, it is
  // gone (a mission script stopped with Ctrl-C or killed), and nothing would cancel its goal.
  for (const char* topic : {"/status", "/feedback", "/result"}) {
    for (const std::string& node : subscribersOf(action_name_ + topic)) {
      if (node == client_) return false;
    }
  }
  why = "its client " + client_ + " disconnected";
  return true;
}

void MoveBaseServer::feedback(const nav_msgs::Odometry& odom) {
  if (!active_) return;
  move_base_msgs::MoveBaseFeedback f;
  f.base_position.header = odom.header;
  f.base_position.pose = odom.pose.pose;
  active_->publishFeedback(f);
}

void MoveBaseServer::onSimpleGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  if (!started_) {
    ROS_WARN("goal on %s refused: not ready (no odometry, scan or map yet)",
             goal_sub_.getTopic().c_str());
    report("refused: not ready (no odometry, scan or map yet)");
    return;
  }
  move_base_msgs::MoveBaseActionGoal goal;
  goal.header.stamp = ros::Time::now();
  goal.goal.target_pose = *msg;
  action_goal_pub_.publish(goal);
}

void MoveBaseServer::onCancel(Server::GoalHandle handle) {
  // Goals are taken or ended as they come, so only the active one can be canceled.
  if (!active_ || *active_ != handle) return;
  active_->setCanceled(move_base_msgs::MoveBaseResult(), "canceled");  // PREEMPTED
  clear();
  ROS_INFO("goal canceled; the robot stops");
  canceled_();
  report("canceled");
}

void MoveBaseServer::report(const std::string& outcome) {
  std_msgs::String msg;
  msg.data = outcome;
  outcome_pub_.publish(msg);
}

bool MoveBaseServer::transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                               Eigen::Vector2d& out, double& yaw, std::string& why) const {
  try {
    const geometry_msgs::PoseStamped in_frame = map_.tf().transform(msg, frame, ros::Duration(0.2));
    out = Eigen::Vector2d(in_frame.pose.position.x, in_frame.pose.position.y);
    yaw = tf2::getYaw(in_frame.pose.orientation);
    return true;
  } catch (const tf2::TransformException& e) {
    why =
        "cannot transform it from '" + msg.header.frame_id + "' into '" + frame + "': " + e.what();
    return false;
  }
}

void MoveBaseServer::onActionGoal(Server::GoalHandle handle) {
  if (active_) {
    // A new goal preempts the current one (PREEMPTED), as move_base's does.
    active_->setCanceled(move_base_msgs::MoveBaseResult(), "preempted by a new goal");
    clear();
    report("preempted");
  }
  handle.setAccepted();
  active_ = handle;
  // Its client is watched while it stays connected; a goal sent on a topic by hand is not.
  const std::string sender = goalSender(handle.getGoalID().id);
  for (const std::string& node : subscribersOf(action_name_ + "/status")) {
    if (!sender.empty() && node == sender) client_ = sender;
  }
  take(handle.getGoal()->target_pose);
}

void MoveBaseServer::take(const geometry_msgs::PoseStamped& target) {
  const auto refuse = [this](const std::string& why) { abort("refused: " + why); };
  if (!finitePose(target.pose)) return refuse("its pose is not finite");
  const auto& q = target.pose.orientation;
  if (std::abs(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w - 1.0) > 1e-2) {
    return refuse("its orientation is no unit quaternion");
  }
  const std::string frame = odom_frame_();
  if (frame.empty()) return refuse("no odometry yet (its frame is unknown)");
  Eigen::Vector2d goal, in_map;
  double yaw = 0.0, map_yaw = 0.0;
  std::string why;
  if (!transform(target, frame, goal, yaw, why)) return refuse(why);
  if (map_.map()) {
    // The map's cells are looked up in the map's own frame: a drifting map -> odom is followed.
    const std::string& map_frame = map_.mapFrame().empty() ? frame : map_.mapFrame();
    if (!transform(target, map_frame, in_map, map_yaw, why)) return refuse(why);
    if (!map_.onFreeCell(in_map, why)) {
      return refuse("(" + std::to_string(in_map.x()) + ", " + std::to_string(in_map.y()) + ") in " +
                    map_frame + " is " + why);
    }
    goal_in_map_ = in_map;
  }
  goal_ = goal;
  goal_yaw_ = yaw;
  current_goal_pub_.publish(target);
  goal_marker_pub_.publish(goalMarker(target, visualization_msgs::Marker::ADD));
  shown_frame_ = target.header.frame_id;
  accepted_();
  ROS_INFO("new goal (%.2f, %.2f) in %s", goal.x(), goal.y(), frame.c_str());
  report("accepted");
}

}  // namespace jetbot_rl
