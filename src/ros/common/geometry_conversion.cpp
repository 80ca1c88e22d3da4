#include "jetbot_rl/ros/common/geometry_conversion.h"

#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace jetbot_rl {

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
  const Eigen::Quaterniond q = yawQuaternion(map.origin_yaw);
  grid.info.origin.orientation.x = q.x();
  grid.info.origin.orientation.y = q.y();
  grid.info.origin.orientation.z = q.z();
  grid.info.origin.orientation.w = q.w();
  grid.data.assign(map.data.begin(), map.data.end());
  return grid;
}

RootState rootStateOf(const nav_msgs::Odometry& odometry) {
  const auto& pose = odometry.pose.pose;
  const auto& v = odometry.twist.twist;
  RootState state;
  state.position = {pose.position.x, pose.position.y, pose.position.z};
  state.orientation = Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y,
                                         pose.orientation.z)
                          .normalized();
  state.com_linear_velocity =
      state.orientation * Eigen::Vector3d(v.linear.x, v.linear.y, v.linear.z);
  state.angular_velocity =
      state.orientation * Eigen::Vector3d(v.angular.x, v.angular.y, v.angular.z);
  return state;
}

void setPose(geometry_msgs::Pose& pose, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  pose.position.x = p.x();
  pose.position.y = p.y();
  pose.position.z = p.z();
  pose.orientation.x = q.x();
  pose.orientation.y = q.y();
  pose.orientation.z = q.z();
  pose.orientation.w = q.w();
}

Eigen::Quaterniond yawQuaternion(double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
}

Eigen::Isometry3d toIsometry(const geometry_msgs::Transform& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
  pose.linear() = Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z)
                      .normalized()
                      .toRotationMatrix();
  return pose;
}

void toTransform(const Eigen::Isometry3d& pose, geometry_msgs::Transform& t) {
  const Eigen::Vector3d p = pose.translation();
  const Eigen::Quaterniond q = Eigen::Quaterniond(pose.rotation()).normalized();
  t.translation.x = p.x();
  t.translation.y = p.y();
  t.translation.z = p.z();
  t.rotation.x = q.x();
  t.rotation.y = q.y();
  t.rotation.z = q.z();
  t.rotation.w = q.w();
}

}  // namespace jetbot_rl
