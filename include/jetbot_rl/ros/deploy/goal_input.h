#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "jetbot_rl/occupancy_map.h"

namespace jetbot_rl {

/// The grid of an OccupancyGrid message as the core's OccupancyMap (cells, resolution, origin).
OccupancyMap occupancyMapOf(const nav_msgs::OccupancyGrid& grid);

/**
 * Goals for a task with one (navigation): PoseStamped goals as RViz's "2D Nav Goal" publishes
 * them, transformed into the odometry frame with tf2 and, with a map, into the map's frame
 * (its header's) and checked against its free cells there; what became of each goal (accepted,
 * reached, refused: why) is published as a std_msgs/String.
 */
class GoalInput {
 public:
  /// The odometry frame, or "" before any odometry came.
  using OdomFrame = std::function<std::string()>;

  /// `goal_topic` and `outcome_topic` may be private ("~name"); `map_topic` "" checks no map.
  /// `accepted` is called for each new goal (a new episode starts).
  GoalInput(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& goal_topic,
            const std::string& outcome_topic, const std::string& map_topic, OdomFrame odom_frame,
            std::function<void()> accepted);

  /// The current goal in the odometry frame, or none (no goal yet, reached or refused).
  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }
  /// The current goal in the map's frame (with a map).
  const std::optional<Eigen::Vector2d>& goalInMap() const { return goal_in_map_; }
  /// The last valid map on the map topic, if any came, its frame, and how many came.
  const std::optional<OccupancyMap>& map() const { return map_; }
  const std::string& mapFrame() const { return map_frame_; }
  int mapsReceived() const { return maps_received_; }
  /// The tf2 buffer goals are transformed with.
  const tf2_ros::Buffer& tf() const { return tf_buffer_; }
  /// Ends the current goal with `outcome` (e.g. "reached").
  void end(const std::string& outcome);
  std::string topic() const { return goal_sub_.getTopic(); }

 private:
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void refuse(const std::string& why);
  void report(const std::string& outcome);
  /// True when `goal` (the map's frame) lies on a free cell of the map, or no map is given.
  bool onFreeCell(const Eigen::Vector2d& goal, std::string& why) const;
  /// `msg` in `frame` (x, y), or false with `why`.
  bool transform(const geometry_msgs::PoseStamped& msg, const std::string& frame,
                 Eigen::Vector2d& out, std::string& why) const;

  OdomFrame odom_frame_;
  std::function<void()> accepted_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Publisher outcome_pub_;
  ros::Subscriber goal_sub_, map_sub_;
  std::optional<OccupancyMap> map_;
  std::string map_frame_;
  int maps_received_ = 0;
  std::optional<Eigen::Vector2d> goal_, goal_in_map_;
};

}  // namespace jetbot_rl
