#include "jetbot_rl/ros/env_node/map_publisher.h"

#include <nav_msgs/MapMetaData.h>

#include <Eigen/Geometry>

namespace jetbot_rl {

nav_msgs::OccupancyGrid toOccupancyGrid(const OccupancyMap& map, const std::string& frame_id,
                                        const ros::Time& stamp) {
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = frame_id;
  grid.header.stamp = stamp;
  grid.info.map_load_time = stamp;
  grid.info.resolution = static_cast<float>(map.resolution);
  grid.info.width = static_cast<std::uint32_t>(map.width);
  grid.info.height = static_cast<std::uint32_t>(map.height);
  grid.info.origin.position.x = map.origin_x;
  grid.info.origin.position.y = map.origin_y;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(map.origin_yaw, Eigen::Vector3d::UnitZ()));
  grid.info.origin.orientation.x = q.x();
  grid.info.origin.orientation.y = q.y();
  grid.info.origin.orientation.z = q.z();
  grid.info.origin.orientation.w = q.w();
  grid.data.assign(map.data.begin(), map.data.end());
  return grid;
}

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
