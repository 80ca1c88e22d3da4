#pragma once

#include <nav_msgs/OccupancyGrid.h>
#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <Eigen/Core>
#include <optional>
#include <string>

#include "jetbot_rl/world/occupancy_map.h"

namespace jetbot_rl {

/**
 * The deploy node's view of the world around a goal: the map (a nav_msgs/OccupancyGrid, as
 * map_server latches it; an invalid one is ignored with a warning), its free cells, and the tf2
 * buffer and listener the goals, the plans and the scan are transformed with. One MapInput is
 * lent to the move_base server (checking goals) and the path follower (planning on the map).
 */
class MapInput {
 public:
  /// Subscribes to `map_topic` (resolved in `nh`'s namespace); "" takes no map (every goal is on
  /// a free cell then).
  MapInput(ros::NodeHandle& nh, const std::string& map_topic);
  MapInput(const MapInput&) = delete;
  MapInput& operator=(const MapInput&) = delete;

  /// The last valid map on the map topic, if any came, its frame, and how many came.
  const std::optional<OccupancyMap>& map() const { return map_; }
  const std::string& mapFrame() const { return map_frame_; }
  int mapsReceived() const { return maps_received_; }
  /// The map topic ("" without one).
  std::string topic() const { return map_sub_ ? map_sub_.getTopic() : std::string(); }
  /// The tf2 buffer goals, plans and scans are transformed with.
  const tf2_ros::Buffer& tf() const { return tf_buffer_; }
  /// `q` (the map's frame) in `frame` through tf's latest transform, or none without one.
  std::optional<Eigen::Vector2d> fromMap(const Eigen::Vector2d& q, const std::string& frame) const;
  /// True when `point` (the map's frame) lies on a free cell of the map, or no map came; else
  /// false with `why` (outside the map, an unknown cell, an obstacle).
  bool onFreeCell(const Eigen::Vector2d& point, std::string& why) const;

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::Subscriber map_sub_;
  std::optional<OccupancyMap> map_;
  std::string map_frame_;
  int maps_received_ = 0;
};

}  // namespace jetbot_rl
