#pragma once

#include <ros/node_handle.h>
#include <visualization_msgs/MarkerArray.h>

#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

/// Markers of a Gazebo world's collision geometry in frame `frame_id`: a CUBE or CYLINDER per
/// upright box or cylinder, one TRIANGLE_LIST of every other shape's surface (namespace
/// "gazebo_world").
visualization_msgs::MarkerArray worldGeometryMarkers(const WorldModel& world,
                                                     const std::string& frame_id);

/// Latches world_geometry (in the node's namespace, after robot_prefix) once, in env 0's map frame
/// as /map: RViz shows the Gazebo world's shapes (those crossing the cut) over its grid.
class WorldGeometryPublisher {
 public:
  WorldGeometryPublisher(ros::NodeHandle& nh, const WorldModel& world, const RobotNames& names);

 private:
  ros::Publisher pub_;
};

}  // namespace jetbot_rl
