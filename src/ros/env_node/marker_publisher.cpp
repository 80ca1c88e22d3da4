#include "jetbot_rl/ros/env_node/marker_publisher.h"

#include <algorithm>
#include <cmath>

#include "jetbot_rl/ros/common/geometry_conversion.h"

namespace jetbot_rl {
namespace {

constexpr double kArrowLength = 0.25;     // [m]
constexpr double kArrowHeight = 0.09;     // above the root link origin [m]
constexpr double kShaftDiameter = 0.015;  // [m]
constexpr double kHeadDiameter = 0.03;    // [m]

/// A distinct colour per env: hues spaced by the golden angle.
std_msgs::ColorRGBA envColour(int env, double lighten) {
  const double h = std::fmod(env * 0.618033988749895, 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  const int sector = static_cast<int>(h);
  double r = 0, g = 0, b = 0;
  switch (sector) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
  }
  std_msgs::ColorRGBA c;
  c.r = static_cast<float>(r + (1 - r) * lighten);
  c.g = static_cast<float>(g + (1 - g) * lighten);
  c.b = static_cast<float>(b + (1 - b) * lighten);
  c.a = 1.0f;
  return c;
}

visualization_msgs::Marker marker(const std::string& ns, int id, int type,
                                  const std_msgs::ColorRGBA& colour) {
  visualization_msgs::Marker m;
  m.header.frame_id = "world";
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.color = colour;
  m.pose.orientation.w = 1.0;
  return m;
}

}  // namespace

EnvMarkerPublisher::EnvMarkerPublisher(ros::NodeHandle& pnh, const BatchedEnv& env, int envs,
                                       double rate, bool enabled, CountedSubscriberQueues& queues)
    : envs_(std::clamp(envs, 0, env.numEnvs())),
      enabled_(enabled),
      arrow_task_(capability<ArrowDrawing>(env.task())),
      arrows_(arrow_task_ ? static_cast<int>(arrow_task_->arrowNames().size()) : 0),
      gate_(rate) {
  pub_ = advertiseCounted<visualization_msgs::MarkerArray>(pnh, "markers", 1, queues,
                                                           /*latch=*/true);
  if (!enabled_) {
    deleteAll();
    return;
  }
  // The chassis box: the root body's first box collision, else a 10 cm cube at the root.
  Eigen::Vector3d size(0.1, 0.1, 0.1);
  body_offset_ = Eigen::Isometry3d::Identity();
  for (const auto& g : env.robot().bodies()[0].collisions) {
    if (g.type == CollisionGeometry::Type::kBox) {
      size = g.size;
      body_offset_ = g.origin;
      break;
    }
  }
  const std::vector<std::string> arrow_names =
      arrow_task_ ? arrow_task_->arrowNames() : std::vector<std::string>();
  for (int e = 0; e < envs_; ++e) {
    auto body = marker("body", e, visualization_msgs::Marker::CUBE, envColour(e, 0.0));
    body.scale.x = size.x();
    body.scale.y = size.y();
    body.scale.z = size.z();
    body.color.a = 0.5f;  // lets a RobotModel display show through
    array_.markers.push_back(body);
    auto forward = marker("forward", e, visualization_msgs::Marker::ARROW, envColour(e, 0.0));
    forward.scale.x = kArrowLength;
    forward.scale.y = kShaftDiameter;
    forward.scale.z = kHeadDiameter;
    array_.markers.push_back(forward);
    for (const std::string& name : arrow_names) {
      auto arrow = marker(name, e, visualization_msgs::Marker::ARROW, envColour(e, 0.6));
      arrow.scale = forward.scale;
      array_.markers.push_back(arrow);
    }
  }
  // The world's walls and obstacles, per env: placed at every capture from its layout.
  if (const WorldModel* world = env.world()) {
    std_msgs::ColorRGBA grey;
    grey.r = grey.g = grey.b = 0.55f;
    grey.a = 0.8f;
    const int per_env =
        static_cast<int>(world->walls().size() + env.view(0).layout().obstacles.size());
    for (int e = 0; e < envs_; ++e) {
      for (int k = 0; k < per_env; ++k) {
        array_.markers.push_back(
            marker("world", e * per_env + k, visualization_msgs::Marker::CUBE, grey));
      }
    }
    // The movers, per env: moved at every capture (orange, to tell them from the still world).
    std_msgs::ColorRGBA orange;
    orange.r = 1.0f;
    orange.g = 0.55f;
    orange.b = 0.1f;
    orange.a = 0.9f;
    const int movers = static_cast<int>(env.view(0).movers().size());
    for (int e = 0; e < envs_; ++e) {
      for (int k = 0; k < movers; ++k) {
        array_.markers.push_back(
            marker("movers", e * movers + k, visualization_msgs::Marker::CYLINDER, orange));
      }
    }
  }
}

void EnvMarkerPublisher::finish() {
  if (enabled_) deleteAll();
}

void EnvMarkerPublisher::deleteAll() {
  visualization_msgs::MarkerArray clear;
  clear.markers.emplace_back();
  clear.markers[0].header.frame_id = "world";
  clear.markers[0].action = visualization_msgs::Marker::DELETEALL;
  pub_.publish(clear);
}

void EnvMarkerPublisher::capture(const BatchedEnv& env, const EnvStep::ConstPtr& msg, bool reset) {
  if (!enabled_ || envs_ == 0 || !gate_.due(msg->header.stamp, reset)) return;
  const ros::Time& stamp = msg->header.stamp;
  std::size_t k = 0;
  for (int e = 0; e < envs_; ++e) {
    const RootState s = env.view(e).rootState();
    Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
    root.linear() = s.orientation.toRotationMatrix();
    root.translation() = env.view(e).origin() + s.position;
    const Eigen::Isometry3d body = root * body_offset_;
    const Eigen::Vector3d forward = s.orientation * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d arrow_base = root.translation() + Eigen::Vector3d(0, 0, kArrowHeight);

    auto& body_marker = array_.markers[k++];
    body_marker.header.stamp = stamp;
    setPose(body_marker.pose, body.translation(), Eigen::Quaterniond(body.rotation()));
    auto& forward_marker = array_.markers[k++];
    forward_marker.header.stamp = stamp;
    setPose(forward_marker.pose, arrow_base, yawQuaternion(std::atan2(forward.y(), forward.x())));
    for (int a = 0; a < arrows_; ++a) {
      const Eigen::Vector2d c = arrow_task_->arrowDirection(e, a);
      auto& arrow_marker = array_.markers[k++];
      arrow_marker.header.stamp = stamp;
      setPose(arrow_marker.pose, arrow_base + Eigen::Vector3d(0, 0, 0.01 * (a + 1)),
              yawQuaternion(std::atan2(c.y(), c.x())));
    }
  }
  if (const WorldModel* world = env.world()) {
    const auto place = [&](int e, const Obstacle& o) {
      auto& m = array_.markers[k++];
      m.header.stamp = stamp;
      m.type = o.shape == Obstacle::Shape::kBox ? visualization_msgs::Marker::CUBE
                                                : visualization_msgs::Marker::CYLINDER;
      const bool box = o.shape == Obstacle::Shape::kBox;
      m.scale.x = box ? 2 * o.half_extents.x() : 2 * o.radius;
      m.scale.y = box ? 2 * o.half_extents.y() : 2 * o.radius;
      m.scale.z = o.height;
      m.action = o.placed ? visualization_msgs::Marker::ADD : visualization_msgs::Marker::DELETE;
      const Eigen::Vector3d c =
          env.view(e).origin() + Eigen::Vector3d(o.center.x(), o.center.y(), 0.5 * o.height);
      setPose(m.pose, c, yawQuaternion(o.yaw));
    };
    for (int e = 0; e < envs_; ++e) {
      for (const Obstacle& w : world->walls()) place(e, w);
      for (const Obstacle& o : env.view(e).layout().obstacles) place(e, o);
    }
    for (int e = 0; e < envs_; ++e) {
      for (const Obstacle& o : env.view(e).movers()) place(e, o);
    }
  }
  due_ = true;
}

void EnvMarkerPublisher::send() {
  if (due_) pub_.publish(array_);
  due_ = false;
}

}  // namespace jetbot_rl
