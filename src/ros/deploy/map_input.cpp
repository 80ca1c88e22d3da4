#include "jetbot_rl/ros/deploy/map_input.h"

#include <ros/console.h>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/deploy/planar_transform.h"

namespace jetbot_rl {

MapInput::MapInput(ros::NodeHandle& nh, const std::string& map_topic) : tf_listener_(tf_buffer_) {
  if (!map_topic.empty()) map_sub_ = nh.subscribe(map_topic, 1, &MapInput::onMap, this);
}

void MapInput::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
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

bool MapInput::onFreeCell(const Eigen::Vector2d& point, std::string& why) const {
  if (!map_) return true;
  int x = 0, y = 0;
  if (!map_->cellOf(point, x, y)) {
    why = "outside the map";
    return false;
  }
  if (!map_->isFree(x, y)) {
    why = map_->at(x, y) == -1 ? "on an unknown cell of the map" : "in an obstacle of the map";
    return false;
  }
  return true;
}

std::optional<Eigen::Vector2d> MapInput::fromMap(const Eigen::Vector2d& q,
                                                 const std::string& frame) const {
  Eigen::Isometry2d frame_map;
  std::string why;
  if (!lookupPlanar(tf_buffer_, frame, map_frame_, frame_map, why)) return std::nullopt;
  return frame_map * q;
}

}  // namespace jetbot_rl
