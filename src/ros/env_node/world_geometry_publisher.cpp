#include "jetbot_rl/ros/env_node/world_geometry_publisher.h"

#include <Eigen/Geometry>

#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {

visualization_msgs::MarkerArray worldGeometryMarkers(const WorldModel& world,
                                                     const std::string& frame_id) {
  visualization_msgs::MarkerArray array;
  const GazeboWorld* gazebo = world.gazebo();
  if (!gazebo) return array;
  const auto marker = [&](int type) {
    visualization_msgs::Marker m;
    m.header.frame_id = frame_id;
    m.ns = "gazebo_world";
    m.id = static_cast<int>(array.markers.size());
    m.type = type;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color.r = m.color.g = 0.6f;
    m.color.b = 0.5f;
    m.color.a = 0.9f;
    return m;
  };
  visualization_msgs::Marker surfaces = marker(visualization_msgs::Marker::TRIANGLE_LIST);
  surfaces.id = -1;  // set below, after the upright ones
  for (const WorldSolid& s : gazebo->solids) {
    if (!crossesHeight(s, world.cutHeight())) continue;
    if (!s.upright) {
      for (const Eigen::Vector3d& p : s.triangles) {
        geometry_msgs::Point q;
        q.x = p.x();
        q.y = p.y();
        q.z = p.z();
        surfaces.points.push_back(q);
      }
      continue;
    }
    const Obstacle& o = *s.upright;
    const bool box = o.shape == Obstacle::Shape::kBox;
    visualization_msgs::Marker m =
        marker(box ? visualization_msgs::Marker::CUBE : visualization_msgs::Marker::CYLINDER);
    m.scale.x = box ? 2.0 * o.half_extents.x() : 2.0 * o.radius;
    m.scale.y = box ? 2.0 * o.half_extents.y() : 2.0 * o.radius;
    m.scale.z = s.top - s.bottom;
    m.pose.position.x = o.center.x();
    m.pose.position.y = o.center.y();
    m.pose.position.z = 0.5 * (s.top + s.bottom);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ()));
    m.pose.orientation.z = q.z();
    m.pose.orientation.w = q.w();
    array.markers.push_back(m);
  }
  if (!surfaces.points.empty()) {
    surfaces.id = static_cast<int>(array.markers.size());
    array.markers.push_back(surfaces);
  }
  return array;
}

WorldGeometryPublisher::WorldGeometryPublisher(ros::NodeHandle& nh, const WorldModel& world,
                                               const RobotNames& names) {
  pub_ = nh.advertise<visualization_msgs::MarkerArray>(names.nodePrefix() + "world_geometry", 1,
                                                       /*latch=*/true);
  pub_.publish(worldGeometryMarkers(world, names.frame(0, "map")));
}

}  // namespace jetbot_rl
