#include "jetbot_rl/ppo/ros/navigation_driver.h"

#include <ros/ros.h>
#include <std_msgs/String.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>

#include "jetbot_rl/config_fields.h"
#include "jetbot_rl/navigation_task.h"
#include "jetbot_rl/ros/common/publication_flush.h"

namespace jetbot_rl {
namespace ppo {
namespace {

constexpr double kTwoPi = 6.283185307179586;

double yawOf(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

bool finitePose(const geometry_msgs::Pose& p) {
  for (double x : {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y,
                   p.orientation.z, p.orientation.w}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

}  // namespace

std::vector<float> resampleScan(const sensor_msgs::LaserScan& scan,
                                const std::vector<double>& beam_angles, double range_min,
                                double range_max, std::string& error) {
  const int n = static_cast<int>(scan.ranges.size());
  const double inc = scan.angle_increment;
  if (n == 0 || !std::isfinite(inc) || inc == 0.0 || !std::isfinite(scan.angle_min)) {
    error = "the scan has no ranges or no angle increment";
    return {};
  }
  const double span = inc * n;  // the angle the samples cover
  const bool full_turn = std::abs(span) >= kTwoPi - std::abs(inc) * 1.5;
  std::vector<float> beams;
  for (double angle : beam_angles) {
    double k = (angle - scan.angle_min) / inc;
    if (full_turn) {
      k = std::fmod(k, static_cast<double>(n));
      if (k < 0) k += n;
    }
    int i = static_cast<int>(std::lround(k));
    if (full_turn) i %= n;
    if (i < 0 || i >= n) {
      error = "the scan covers [" + std::to_string(scan.angle_min) + ", " +
              std::to_string(scan.angle_min + inc * (n - 1)) +
              "] rad; the policy needs a beam at " + std::to_string(angle) + " rad";
      return {};
    }
    double r = scan.ranges[i];
    if (std::isnan(r) || r == std::numeric_limits<float>::infinity()) r = range_max;
    if (r == -std::numeric_limits<float>::infinity()) r = range_min;
    r = std::min(std::max(r, range_min), range_max);
    beams.push_back(static_cast<float>(r / range_max));
  }
  return beams;
}

ScanBeams scanBeamsOf(const BatchSpec& trained, const RobotModeParams& p,
                      const std::string& checkpoint) {
  ScanBeams beams;
  if (trained.scan_beam_angles.empty() || trained.scan_range.size() != 2) {
    if (p.scan_angles.empty() || p.scan_range.empty()) {
      throwInvalid(p.scan_angles.empty() ? "scan_angles" : "scan_range", "[]",
                   "checkpoint " + checkpoint +
                       " does not hold the scan beams it was trained on (written before "
                       "checkpoints held them): give the trained scanner's scan_angles [first, "
                       "last] and scan_range [min, max]");
    }
    const int k = p.task.navigation.beams;
    for (int i = 0; i < k; ++i) {
      beams.angles.push_back(k == 1 ? p.scan_angles[0]
                                    : p.scan_angles[0] +
                                          i * (p.scan_angles[1] - p.scan_angles[0]) / (k - 1));
    }
    beams.range_min = p.scan_range[0];
    beams.range_max = p.scan_range[1];
    return beams;
  }
  beams.angles = trained.scan_beam_angles;
  beams.range_min = trained.scan_range[0];
  beams.range_max = trained.scan_range[1];
  // Given as well: they must say what the checkpoint says (anything else would misread the scan).
  const auto agree = [&](const char* name, const std::vector<double>& given, double first,
                         double last, const char* unit) {
    if (given.empty()) return;
    if (std::abs(given[0] - first) > 1e-6 || std::abs(given[1] - last) > 1e-6) {
      throwInvalid(name, listText(given),
                   std::string("the policy of ") + checkpoint + " was trained with " +
                       listText(std::vector<double>{first, last}) + " " + unit +
                       " (leave it unset: the checkpoint gives it)");
    }
  };
  agree("scan_angles", p.scan_angles, beams.angles.front(), beams.angles.back(), "rad");
  agree("scan_range", p.scan_range, beams.range_min, beams.range_max, "m");
  return beams;
}

NavigationDriver::NavigationDriver(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy,
                                   const RobotModeParams& p, const PolicyRun& run,
                                   const std::optional<DiffDrive>& kinematics)
    : params_(p),
      policy_(policy),
      run_(run),
      kinematics_(kinematics),
      tf_listener_(tf_buffer_),
      dropped_(nh, ros::this_node::getName() + ": robot mode", "dropped input") {
  beams_of_policy_ = scanBeamsOf(policy.meta().spec, p, run.checkpoint);
  const int beams = static_cast<int>(beams_of_policy_.angles.size());
  const int obs_dim = beams + 5 + 2;
  if (obs_dim != policy_.obsDim()) {
    throw ConfigError("task 'navigation' with " + std::to_string(beams) + " beams observes " +
                      std::to_string(obs_dim) + " values; the policy takes " +
                      std::to_string(policy_.obsDim()));
  }
  if (!run.twist && !kinematics_) throw Error("NavigationDriver: wheel actions need kinematics");
  last_action_.assign(2, 0.0f);
  const auto topic = [&](const std::string& name) -> ros::NodeHandle& {
    return name.rfind('~', 0) == 0 ? pnh : nh;
  };
  const auto strip = [](const std::string& name) {
    return name.rfind('~', 0) == 0 ? name.substr(1) : name;
  };
  cmd_vel_pub_ = nh.advertise<geometry_msgs::Twist>(p.cmd_vel_topic, 10);
  outcome_pub_ = topic(p.outcome_topic).advertise<std_msgs::String>(strip(p.outcome_topic), 10);
  odom_sub_ = nh.subscribe(p.odom_topic, 10, &NavigationDriver::onOdom, this,
                           ros::TransportHints().tcpNoDelay());
  scan_sub_ = nh.subscribe(p.scan_topic, 10, &NavigationDriver::onScan, this,
                           ros::TransportHints().tcpNoDelay());
  goal_sub_ =
      topic(p.goal_topic).subscribe(strip(p.goal_topic), 10, &NavigationDriver::onGoal, this);
  if (!p.map_topic.empty()) map_sub_ = nh.subscribe(p.map_topic, 1, &NavigationDriver::onMap, this);
  timer_ = nh.createWallTimer(ros::WallDuration(1.0 / run.control_rate), &NavigationDriver::onTick,
                              this);
  ROS_INFO(
      "robot mode (navigation): %s, %s and goals on %s -> policy (%d beams over [%g, %g] "
      "rad, range [%g, %g] m: %s) -> %s at %.1f Hz (%s actions; the checkpoint's)",
      odom_sub_.getTopic().c_str(), scan_sub_.getTopic().c_str(), goal_sub_.getTopic().c_str(),
      beams, beams_of_policy_.angles.front(), beams_of_policy_.angles.back(),
      beams_of_policy_.range_min, beams_of_policy_.range_max,
      policy.meta().spec.scan_beam_angles.empty() ? "the parameters'" : "the checkpoint's",
      cmd_vel_pub_.getTopic().c_str(), run.control_rate, run.twist ? "twist" : "wheel");
}

void NavigationDriver::stop() {
  timer_.stop();
  cmd_vel_pub_.publish(geometry_msgs::Twist());
  flushPublications(0.5);
}

void NavigationDriver::report(const std::string& outcome) {
  std_msgs::String msg;
  msg.data = outcome;
  outcome_pub_.publish(msg);
}

void NavigationDriver::onOdom(const nav_msgs::Odometry::ConstPtr& msg) {
  if (!finitePose(msg->pose.pose) || !std::isfinite(msg->twist.twist.linear.x) ||
      !std::isfinite(msg->twist.twist.angular.z)) {
    dropped_.drop("odometry on " + odom_sub_.getTopic() + " with a non-finite value: dropped");
    return;
  }
  odom_ = msg;
  odom_time_ = std::chrono::steady_clock::now();
}

void NavigationDriver::onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  std::string error;
  resampleScan(*msg, beams_of_policy_.angles, beams_of_policy_.range_min,
               beams_of_policy_.range_max, error);
  if (!error.empty()) {
    if (scan_error_.empty())
      ROS_ERROR("scan on %s refused: %s", scan_sub_.getTopic().c_str(), error.c_str());
    scan_error_ = error;
    dropped_.drop("scan on " + scan_sub_.getTopic() + " refused: " + error);
    return;
  }
  scan_error_.clear();
  scan_ = msg;
  scan_time_ = std::chrono::steady_clock::now();
}

void NavigationDriver::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) { map_ = msg; }

bool NavigationDriver::onFreeCell(const Eigen::Vector2d& goal, std::string& why) const {
  if (!map_) return true;
  const auto& info = map_->info;
  const double yaw = yawOf(info.origin.orientation);
  const Eigen::Vector2d rel =
      Eigen::Rotation2Dd(-yaw) *
      (goal - Eigen::Vector2d(info.origin.position.x, info.origin.position.y));
  const int x = static_cast<int>(std::floor(rel.x() / info.resolution));
  const int y = static_cast<int>(std::floor(rel.y() / info.resolution));
  if (x < 0 || y < 0 || x >= static_cast<int>(info.width) || y >= static_cast<int>(info.height)) {
    why = "outside the map";
    return false;
  }
  const int cell = map_->data[static_cast<std::size_t>(y) * info.width + x];
  if (cell != 0) {
    why = cell == -1 ? "on an unknown cell of the map" : "in an obstacle of the map";
    return false;
  }
  return true;
}

void NavigationDriver::onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  const auto refuse = [&](const std::string& why) {
    ROS_WARN("goal refused: %s; the robot stays stopped", why.c_str());
    goal_.reset();
    report("refused: " + why);
  };
  if (!finitePose(msg->pose)) return refuse("its pose is not finite");
  if (!odom_) return refuse("no odometry yet (its frame is unknown)");
  geometry_msgs::PoseStamped in_odom;
  try {
    in_odom = tf_buffer_.transform(*msg, odom_->header.frame_id, ros::Duration(0.2));
  } catch (const tf2::TransformException& e) {
    return refuse("cannot transform it from '" + msg->header.frame_id + "' into '" +
                  odom_->header.frame_id + "': " + e.what());
  }
  const Eigen::Vector2d goal(in_odom.pose.position.x, in_odom.pose.position.y);
  std::string why;
  if (!onFreeCell(goal, why)) {
    return refuse("(" + std::to_string(goal.x()) + ", " + std::to_string(goal.y()) + ") in " +
                  odom_->header.frame_id + " is " + why);
  }
  goal_ = goal;
  policy_.resetMemory();  // each goal is an episode
  ROS_INFO("new goal (%.2f, %.2f) in %s", goal.x(), goal.y(), odom_->header.frame_id.c_str());
  report("accepted");
}

void NavigationDriver::onTick(const ros::WallTimerEvent&) {
  geometry_msgs::Twist twist;  // zero: stop
  const auto now = std::chrono::steady_clock::now();
  const bool odom_fresh =
      odom_ && now - odom_time_ <= std::chrono::duration<double>(params_.odom_timeout);
  const bool scan_fresh =
      scan_ && now - scan_time_ <= std::chrono::duration<double>(params_.scan_timeout);
  if (!goal_) {
    last_action_.assign(2, 0.0f);
  } else if (!odom_fresh || !scan_fresh) {
    ROS_WARN_THROTTLE(2.0, "no fresh %s: stopping the robot", !odom_fresh ? "odometry" : "scan");
    last_action_.assign(2, 0.0f);
    policy_.resetMemory();
  } else {
    const auto& pose = odom_->pose.pose;
    const Eigen::Vector2d position(pose.position.x, pose.position.y);
    const double yaw = yawOf(pose.orientation);
    const Eigen::Vector2d in_robot = Eigen::Rotation2Dd(-yaw) * (*goal_ - position);
    if (in_robot.norm() < params_.task.navigation.goal_radius) {
      ROS_INFO("goal (%.2f, %.2f) reached", goal_->x(), goal_->y());
      goal_.reset();
      last_action_.assign(2, 0.0f);
      report("reached");
    } else {
      std::string error;
      beams_ = resampleScan(*scan_, beams_of_policy_.angles, beams_of_policy_.range_min,
                            beams_of_policy_.range_max, error);
      obs_.resize(static_cast<std::size_t>(policy_.obsDim()));
      NavigationTask::observation(beams_, in_robot, odom_->twist.twist.linear.x,
                                  odom_->twist.twist.angular.z, last_action_.data(), 2,
                                  obs_.data());
      policy_.act(obs_, 1, actions_);
      last_action_.assign(actions_.begin(), actions_.begin() + 2);
      if (run_.twist) {
        twist.linear.x = actions_[0];
        twist.angular.z = actions_[1];
      } else {
        const PlanarTwist body = kinematics_->bodyTwist({actions_[0], actions_[1]});
        twist.linear.x = body.linear;
        twist.angular.z = body.angular;
      }
    }
  }
  cmd_vel_pub_.publish(twist);
}

}  // namespace ppo
}  // namespace jetbot_rl
