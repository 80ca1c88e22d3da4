#include "jetbot_rl/ros/env_node/map_publisher.h"

#include <nav_msgs/MapMetaData.h>

namespace jetbot_rl {

MapPublisher::MapPublisher(ros::NodeHandle& nh, const OccupancyMap& map, const RobotNames& names) {
  map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>(names.nodePrefix() + "map", 1, /*latch=*/true);
  metadata_pub_ =
      nh.advertise<nav_msgs::MapMetaData>(names.nodePrefix() + "map_metadata", 1, /*latch=*/true);
  const nav_msgs::OccupancyGrid grid =
      toOccupancyGrid(map, names.frame(0, "map"), ros::Time::now());
  metadata_pub_.publish(grid.info);
  map_pub_.publish(grid);
}

}  // namespace jetbot_rl
