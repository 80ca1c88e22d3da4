#include "jetbot_rl/ros/deploy/goal_input.h"

#include <move_base_msgs/MoveBaseActionGoal.h>
#include <ros/console.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>

#include "jetbot_rl/ros/common/peer_links.h"
#include "jetbot_rl/ros/common/private_topic.h"
#include "jetbot_rl/ros/deploy/planar_transform.h"

namespace jetbot_rl {
namespace {

bool finitePose(const geometry_msgs::Pose& p) {
  for (double x : {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y,
                   p.orientation.z, p.orientation.w}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

}  // namespace

OccupancyMap occupancyMapOf(const nav_msgs::OccupancyGrid& grid) {
  OccupancyMap map;
  const auto& info = grid.info;
  map.resolution = info.resolution;
  map.origin_x = info.origin.position.x;
  map.origin_y = info.origin.position.y;
  map.origin_yaw = tf2::getYaw(info.origin.orientation);
  map.width = static_cast<int>(info.width);
  map.height = static_cast<int>(info.height);
  map.data = grid.data;
  return map;
}

GoalInput::GoalInput(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& action_name,
                     const std::string& goal_topic, const std::string& outcome_topic,
                     const std::string& map_topic, OdomFrame odom_frame,
                     std::function<void()> accepted, std::function<void()> canceled)
    : odom_frame_(std::move(odom_frame)),
      accepted_(std::move(accepted)),
      canceled_(std::move(canceled)),
      action_name_(nh.resolveName(action_name)),
      tf_listener_(tf_buffer_) {
  outcome_pub_ = nh.advertise<std_msgs::String>(resolvePrivateTopic(pnh, outcome_topic), 10);
  // actionlib's ActionServer rather than its SimpleActionServer: the goal's id names its client.
  server_ = std::make_unique<Server>(
      nh, action_name_, [this](Server::GoalHandle h) { onActionGoal(h); },
      [this](Server::GoalHandle h) { onCancel(h); }, false);
  // A simple goal becomes an action goal on the server's own goal topic, as move_base sends it.
  action_goal_pub_ = nh.advertise<move_base_msgs::MoveBaseActionGoal>(action_name_ + "/goal", 1);
  current_goal_pub_ = pnh.advertise<geometry_msgs::PoseStamped>("current_goal", 1, true);
  goal_sub_ =
      nh.subscribe(resolvePrivateTopic(pnh, goal_topic), 10, &GoalInput::onSimpleGoal, this);
  if (!map_topic.empty()) map_sub_ = nh.subscribe(map_topic, 1, &GoalInput::onMap, this);
}

GoalInput::~GoalInput() {
  if (active_) active_->setAborted(move_base_msgs::MoveBaseResult(), "shut down");
}

void GoalInput::start() {
  if (started_) return;
  server_->start();
  started_ = true;
  ROS_INFO("the move_base action %s takes goals", action_name_.c_str());
}

void GoalInput::clear() {
  goal_.reset();
  goal_in_map_.reset();
  active_.reset();
  client_.clear();
}

void GoalInput::succeed() {
  if (active_) active_->setSucceeded(move_base_msgs::MoveBaseResult(), "reached");
  clear();
  report("reached");
}

void GoalInput::abort(const std::string& why) {
  ROS_WARN("goal ended: %s; the robot stops", why.c_str());
  if (active_) active_->setAborted(move_base_msgs::MoveBaseResult(), why);
  clear();
  report(why);
}

bool GoalInput::clientGone(std::string& why) const {
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

void GoalInput::feedback(const nav_msgs::Odometry& odom) {
  if (!active_) return;
  move_base_msgs::MoveBaseFeedback f;
  f.base_position.header = odom.header;
  f.base_position.pose = odom.pose.pose;
  active_->publishFeedback(f);
}

void GoalInput::onSimpleGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
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

void GoalInput::onCancel(Server::GoalHandle handle) {
  // Goals are taken or ended as they come, so only the active one can be canceled.
  if (!active_ || *active_ != handle) return;
  active_->setCanceled(move_base_msgs::MoveBaseResult(), "canceled");  // PREEMPTED
  clear();
  ROS_INFO("goal canceled; the robot stops");
  canceled_();
  report("canceled");
}

void GoalInput::report(const std::string& outcome) {
  std_msgs::String msg;
  msg.data = outcome;
  outcome_pub_.publish(msg);
}

void GoalInput::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  if (msg->data.size() != static_cast<std::size_t>(msg->info.width) * msg->info.height ||
      !(msg->info.resolution > 0.0f)) {
    ROS_WARN("map on %s ignored: %zu cells for %u x %u at resolution %g",
             map_sub_.getTopic().c_str(), msg->data.size(), msg->info.width, msg->info.height,
             msg->info.resolution);
    return;
  }
  map_ = occupancyMapOf(*msg);
  map_frame_ = msg->header.frame_id;
  ++maps_received_;
}

bool GoalInput::onFreeCell(const Eigen::Vector2d& goal, std::string& why) const {
  if (!map_) return true;
  int x = 0, y = 0;
  if (!map_->cellOf(goal, x, y)) {
    why = "outside the map";
    return false;
  }
  if (!map_->isFree(x, y)) {
    why = map_->at(x, y) == -1 ? "on an unknown cell of the map" : "in an obstacle of the map";
    return false;
  }
  return true;
}

std::optional<Eigen::Vector2d> GoalInput::fromMap(const Eigen::Vector2d& q,
                                                  const std::string& frame) const {
  Eigen::Isometry2d frame_map;
  std::string why;
  if (!lookupPlanar(tf_buffer_, frame, map_frame_, frame_map, why)) return std::nullopt;
  return frame_map * q;
}

bool GoalInput::transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                          Eigen::Vector2d& out, double& yaw, std::string& why) const {
  try {
    const geometry_msgs::PoseStamped in_frame =
        tf_buffer_.transform(msg, frame, ros::Duration(0.2));
    out = Eigen::Vector2d(in_frame.pose.position.x, in_frame.pose.position.y);
    yaw = tf2::getYaw(in_frame.pose.orientation);
    return true;
  } catch (const tf2::TransformException& e) {
    why =
        "cannot transform it from '" + msg.header.frame_id + "' into '" + frame + "': " + e.what();
    return false;
  }
}

void GoalInput::onActionGoal(Server::GoalHandle handle) {
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

void GoalInput::take(const geometry_msgs::PoseStamped& target) {
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
  if (map_) {
    // The map's cells are looked up in the map's own frame: a drifting map -> odom is followed.
    const std::string& map_frame = map_frame_.empty() ? frame : map_frame_;
    if (!transform(target, map_frame, in_map, map_yaw, why)) return refuse(why);
    if (!onFreeCell(in_map, why)) {
      return refuse("(" + std::to_string(in_map.x()) + ", " + std::to_string(in_map.y()) + ") in " +
                    map_frame + " is " + why);
    }
    goal_in_map_ = in_map;
  }
  goal_ = goal;
  goal_yaw_ = yaw;
  current_goal_pub_.publish(target);
  accepted_();
  ROS_INFO("new goal (%.2f, %.2f) in %s", goal.x(), goal.y(), frame.c_str());
  report("accepted");
}

}  // namespace jetbot_rl
