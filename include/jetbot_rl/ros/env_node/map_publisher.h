#pragma once

#include <nav_msgs/OccupancyGrid.h>
#include <ros/node_handle.h>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/world/occupancy_map.h"

namespace jetbot_rl {

/// Latches map and map_metadata (in the node's namespace, after robot_prefix) once, as map_server
/// does, in env 0's map frame ("<prefix>env_0/map"; tf places every env's map frame at its origin).
class MapPublisher {
 public:
  MapPublisher(ros::NodeHandle& nh, const OccupancyMap& map, const RobotNames& names);

 private:
  ros::Publisher map_pub_, metadata_pub_;
};

}  // namespace jetbot_rl
