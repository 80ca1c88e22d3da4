#include "jetbot_rl/ros/deploy/goal_input.h"

#include <ros/console.h>
#include <std_msgs/String.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>

#include "jetbot_rl/ros/common/private_topic.h"

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
  const auto& q = info.origin.orientation;
  map.resolution = info.resolution;
  map.origin_x = info.origin.position.x;
  map.origin_y = info.origin.position.y;
  map.origin_yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  map.width = static_cast<int>(info.width);
  map.height = static_cast<int>(info.height);
  map.data = grid.data;
  return map;
}

GoalInput::GoalInput(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& goal_topic,
                     const std::string& outcome_topic, const std::string& map_topic,
                     OdomFrame odom_frame, std::function<void()> accepted)
    : odom_frame_(std::move(odom_frame)), accepted_(std::move(accepted)), tf_listener_(tf_buffer_) {
  outcome_pub_ = nh.advertise<std_msgs::String>(resolvePrivateTopic(pnh, outcome_topic), 10);
  goal_sub_ = nh.subscribe(resolvePrivateTopic(pnh, goal_topic), 10, &GoalInput::onGoal, this);
  if (!map_topic.empty()) map_sub_ = nh.subscribe(map_topic, 1, &GoalInput::onMap, this);
}

void GoalInput::end(const std::string& outcome) {
  goal_.reset();
  goal_in_map_.reset();
  report(outcome);
}

void GoalInput::report(const std::string& outcome) {
  std_msgs::String msg;
  msg.data = outcome;
  outcome_pub_.publish(msg);
}

void GoalInput::refuse(const std::string& why) {
  ROS_WARN("goal refused: %s; the robot stays stopped", why.c_str());
  end("refused: " + why);
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

bool GoalInput::transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                          Eigen::Vector2d& out, std::string& why) const {
  try {
    const geometry_msgs::PoseStamped in_frame =
        tf_buffer_.transform(msg, frame, ros::Duration(0.2));
    out = Eigen::Vector2d(in_frame.pose.position.x, in_frame.pose.position.y);
    return true;
  } catch (const tf2::TransformException& e) {
    why =
        "cannot transform it from '" + msg.header.frame_id + "' into '" + frame + "': " + e.what();
    return false;
  }
}

void GoalInput::onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  if (!finitePose(msg->pose)) return refuse("its pose is not finite");
  const std::string frame = odom_frame_();
  if (frame.empty()) return refuse("no odometry yet (its frame is unknown)");
  Eigen::Vector2d goal, in_map;
  std::string why;
  if (!transform(*msg, frame, goal, why)) return refuse(why);
  if (map_) {
    // The map's cells are looked up in the map's own frame: a drifting map -> odom is followed.
    const std::string& map_frame = map_frame_.empty() ? frame : map_frame_;
    if (!transform(*msg, map_frame, in_map, why)) return refuse(why);
    if (!onFreeCell(in_map, why)) {
      return refuse("(" + std::to_string(in_map.x()) + ", " + std::to_string(in_map.y()) + ") in " +
                    map_frame + " is " + why);
    }
    goal_in_map_ = in_map;
  }
  goal_ = goal;
  accepted_();
  ROS_INFO("new goal (%.2f, %.2f) in %s", goal.x(), goal.y(), frame.c_str());
  report("accepted");
}

}  // namespace jetbot_rl
