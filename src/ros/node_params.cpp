#include "jetbot_rl/ros/node_params.h"

#include "jetbot_rl/ros/param_reader.h"

namespace jetbot_rl {

NodeParams loadNodeParams(const ros::NodeHandle& pnh) {
  NodeParams p;
  readFields(pnh, p);
  validateFields(p);
  p.env.validate();  // the rules between fields
  return p;
}

}  // namespace jetbot_rl
