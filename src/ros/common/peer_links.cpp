#include "jetbot_rl/ros/common/peer_links.h"

#include <ros/names.h>
#include <ros/publication.h>
#include <ros/topic_manager.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace jetbot_rl {

std::vector<std::string> subscribersOf(const std::string& topic) {
  std::vector<std::string> nodes;
  const ros::PublicationPtr publication = ros::TopicManager::instance()->lookupPublication(topic);
  if (!publication) return nodes;
  // Publication::getInfo is what the node's getBusInfo (rosnode info) reports: one row per
  // connection, [id, the subscriber's caller id, direction, transport, topic, ...].
  XmlRpc::XmlRpcValue info;
  info.setSize(0);
  publication->getInfo(info);
  for (int i = 0; i < info.size(); ++i) {
    if (info[i].getType() == XmlRpc::XmlRpcValue::TypeArray && info[i].size() > 1 &&
        info[i][1].getType() == XmlRpc::XmlRpcValue::TypeString) {
      nodes.push_back(static_cast<std::string>(info[i][1]));
    }
  }
  return nodes;
}

std::string goalSender(const std::string& goal_id) {
  // A ROS name holds no '-', so the first one ends the node's name.
  const std::size_t dash = goal_id.find('-');
  if (dash == std::string::npos || dash == 0) return "";
  const std::string node = goal_id.substr(0, dash);
  std::string why;
  return ros::names::validate(node, why) && node[0] == '/' ? node : "";
}

}  // namespace jetbot_rl
