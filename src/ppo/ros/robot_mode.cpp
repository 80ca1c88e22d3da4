#include "jetbot_rl/ppo/ros/robot_mode.h"

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <chrono>
#include <cmath>
#include <memory>

#include "jetbot_rl/diff_drive.h"
#include "jetbot_rl/ppo/ros/navigation_driver.h"
#include "jetbot_rl/ros/common/drop_counter.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/publication_flush.h"
#include "jetbot_rl/ros/common/robot_description.h"

namespace jetbot_rl {
namespace ppo {
namespace {

/// Wheel targets -> Twist kinematics: the parameters; one given as 0 from robot_description.
/// `limits`: the policy's wheel velocity bounds [rad/s].
DiffDrive makeKinematics(const ros::NodeHandle& nh, const RobotModeParams& p,
                         const std::vector<double>& limits) {
  if (p.wheel_radius > 0.0 && p.wheel_separation > 0.0) {
    return DiffDrive(p.wheel_radius, p.wheel_separation, {p.dof_names.at(0), 0, 1.0, limits.at(0)},
                     {p.dof_names.at(1), 1, 1.0, limits.at(1)});
  }
  if (!nh.hasParam("robot_description")) {
    throwInvalid(p.wheel_radius > 0.0 ? "wheel_separation" : "wheel_radius", 0.0,
                 "0 takes it from robot_description, which is not set");
  }
  return DiffDrive::fromRobot(*loadRobotDescription(nh), p.dof_names, limits, p.wheel_radius,
                              p.wheel_separation);
}

/// Robot-mode parameters of earlier versions that the checkpoint now gives.
const std::vector<std::pair<const char*, const char*>>& paramsFromTheCheckpoint() {
  static const std::vector<std::pair<const char*, const char*>> removed{
      {"control_rate", "1 / its control step"},
      {"wheel_velocity_limit", "its action bounds"},
      {"twist_limits", "its action bounds"},
      {"policy_actions", "its action names"}};
  return removed;
}

bool finite(const nav_msgs::Odometry& m) {
  const auto& p = m.pose.pose.position;
  const auto& q = m.pose.pose.orientation;
  const auto& v = m.twist.twist.linear;
  const auto& w = m.twist.twist.angular;
  for (double x : {p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, w.x, w.y, w.z}) {
    if (!std::isfinite(x)) return false;
  }
  return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w > 1e-12;
}

/// The robot mode's state: the newest odometry and command, the task that observes them.
class RobotDriver {
 public:
  RobotDriver(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy, const RobotModeParams& p,
              const PolicyRun& run)
      : params_(p),
        policy_(policy),
        kinematics_(makeKinematics(nh, p, run.action_high)),
        task_(makeTask(p.task)),
        dropped_(nh, ros::this_node::getName() + ": robot mode", "dropped odometry") {
    task_->resize(1);
    if (static_cast<int>(task_->observationNames().size()) != policy_.obsDim()) {
      throw ConfigError("task '" + task_->name() + "' observes " +
                        std::to_string(task_->observationNames().size()) +
                        " values; the policy takes " + std::to_string(policy_.obsDim()));
    }
    if (run.twist) {
      throw ConfigError("the policy's actions are a twist (linear_x, angular_z): task '" +
                        task_->name() + "' drives wheel targets");
    }
    cmd_vel_pub_ = nh.advertise<geometry_msgs::Twist>(p.cmd_vel_topic, 10);
    odom_sub_ = nh.subscribe(p.odom_topic, 10, &RobotDriver::onOdom, this,
                             ros::TransportHints().tcpNoDelay());
    if (task_->commandDim() == 2) {
      command_sub_ = (p.command_topic.rfind('~', 0) == 0 ? pnh : nh)
                         .subscribe(p.command_topic.rfind('~', 0) == 0 ? p.command_topic.substr(1)
                                                                       : p.command_topic,
                                    10, &RobotDriver::onCommand, this);
    }
    timer_ =
        nh.createWallTimer(ros::WallDuration(1.0 / run.control_rate), &RobotDriver::onTick, this);
    ROS_INFO("robot mode: %s -> policy (task %s%s) -> %s at %.1f Hz (the checkpoint's); %s",
             odom_sub_.getTopic().c_str(), task_->name().c_str(),
             policy_.hasMemory() ? ", with memory" : "", cmd_vel_pub_.getTopic().c_str(),
             run.control_rate, kinematics_.describe().c_str());
  }

  /// Stops ticking and leaves the robot standing: a zero Twist, written out before returning.
  void stop() {
    timer_.stop();
    cmd_vel_pub_.publish(geometry_msgs::Twist());
    flushPublications(0.5);
  }

 private:
  void onOdom(const nav_msgs::Odometry::ConstPtr& msg) {
    if (!finite(*msg)) {
      dropped_.drop("odometry on " + odom_sub_.getTopic() +
                    " with a non-finite value or a zero quaternion: dropped");
      return;
    }
    odom_ = msg;
    odom_time_ = std::chrono::steady_clock::now();
  }

  void onCommand(const geometry_msgs::Vector3::ConstPtr& msg) {
    try {
      task_->setCommand(0, {msg->x, msg->y}, /*hold=*/true);
      policy_.resetMemory();  // a new command starts a new episode, as in training
    } catch (const InputError& e) {
      ROS_WARN_THROTTLE(1.0, "command ignored: %s", e.what());
    }
  }

  void onTick(const ros::WallTimerEvent&) {
    geometry_msgs::Twist twist;  // zero: stop
    const auto age = std::chrono::steady_clock::now() - odom_time_;
    if (!odom_ || age > std::chrono::duration<double>(params_.odom_timeout)) {
      ROS_WARN_THROTTLE(2.0, "no odometry on %s for over %.2f s: stopping the robot",
                        odom_sub_.getTopic().c_str(), params_.odom_timeout);
      policy_.resetMemory();  // the robot stops: its memory starts over with the next drive
    } else {
      // The task's observation of the odometry: pose in the odom frame, twist in the child frame
      // (rotated into the odom frame, where RootState keeps its velocities).
      const auto& pose = odom_->pose.pose;
      const auto& v = odom_->twist.twist;
      RootState state;
      state.position = {pose.position.x, pose.position.y, pose.position.z};
      state.orientation = Eigen::Quaterniond(pose.orientation.w, pose.orientation.x,
                                             pose.orientation.y, pose.orientation.z)
                              .normalized();
      state.com_linear_velocity =
          state.orientation * Eigen::Vector3d(v.linear.x, v.linear.y, v.linear.z);
      state.angular_velocity =
          state.orientation * Eigen::Vector3d(v.angular.x, v.angular.y, v.angular.z);
      obs_.resize(static_cast<std::size_t>(policy_.obsDim()));
      task_->observe(0, state, obs_.data());
      policy_.act(obs_, 1, actions_);
      const PlanarTwist body = kinematics_.bodyTwist({actions_[0], actions_[1]});
      twist.linear.x = body.linear;
      twist.angular.z = body.angular;
    }
    cmd_vel_pub_.publish(twist);
  }

  RobotModeParams params_;
  Policy& policy_;
  DiffDrive kinematics_;
  std::unique_ptr<Task> task_;
  ros::Publisher cmd_vel_pub_;
  ros::Subscriber odom_sub_, command_sub_;
  ros::WallTimer timer_;
  nav_msgs::Odometry::ConstPtr odom_;
  std::chrono::steady_clock::time_point odom_time_;
  DropCounter dropped_;
  std::vector<float> obs_, actions_;
};

}  // namespace

void checkFieldRules(const RobotModeParams& p) {
  if (p.dof_names.size() != 2) {
    throwInvalid("dof_names", listText(p.dof_names), "must name the two wheel joints");
  }
  if (!p.scan_angles.empty() &&
      (p.scan_angles.size() != 2 || p.scan_angles[0] > p.scan_angles[1])) {
    throwInvalid("scan_angles", listText(p.scan_angles),
                 "must be empty (the checkpoint's) or [first, last], first <= last");
  }
  if (!p.scan_range.empty() && (p.scan_range.size() != 2 || !(p.scan_range[0] < p.scan_range[1]))) {
    throwInvalid("scan_range", listText(p.scan_range),
                 "must be empty (the checkpoint's) or [min, max], min < max");
  }
}

PolicyRun policyRunOf(const Policy& policy, const std::string& checkpoint) {
  const BatchSpec& spec = policy.meta().spec;
  if (spec.control_dt <= 0.0 || spec.action_high.size() != 2) {
    throw ConfigError("checkpoint " + checkpoint +
                      " does not hold the control step and the action bounds it was trained with "
                      "(a checkpoint of format 1): train it again, or resume it for one iteration "
                      "(train.launch resume:=RUN_DIR/checkpoints/latest.pt iterations:=N+1), "
                      "which saves it in format 2");
  }
  PolicyRun run;
  run.control_rate = 1.0 / spec.control_dt;
  run.twist = spec.action_names == std::vector<std::string>{"linear_x", "angular_z"};
  run.action_high.assign(spec.action_high.begin(), spec.action_high.end());
  run.checkpoint = checkpoint;
  return run;
}

int runRobotMode(ros::NodeHandle& nh, ros::NodeHandle& pnh, Policy& policy,
                 const std::string& checkpoint, const std::atomic<bool>& stop) {
  PolicyRun run;
  try {
    for (const auto& [name, now] : paramsFromTheCheckpoint()) {
      if (pnh.hasParam(name)) {
        throwInvalid(name, "(set)", std::string("comes from the checkpoint now (") + now + ")");
      }
    }
    run = policyRunOf(policy, checkpoint);
  } catch (const ConfigError& e) {
    logParamError(pnh, e);
    return 1;
  }
  // The task: the checkpoint's unless given, and then it must be the checkpoint's.
  const std::optional<RobotModeParams> params =
      loadParams<RobotModeParams>(pnh, [&](RobotModeParams& p) {
        const BatchSpec& spec = policy.meta().spec;
        if (!pnh.hasParam("task")) {
          p.task.task = parseEnum<TaskKind>("task", spec.task);
        } else if (enumName(p.task.task) != spec.task) {
          throwInvalid("task", "'" + enumName(p.task.task) + "'",
                       "the checkpoint was trained on task '" + spec.task + "'");
        }
        // Its beam count too, where it holds its beams.
        if (!spec.scan_beam_angles.empty() && !pnh.hasParam("nav/beams")) {
          p.task.navigation.beams = static_cast<int>(spec.scan_beam_angles.size());
        }
        if (p.task.task == TaskKind::kNavigation) scanBeamsOf(spec, p, checkpoint);  // agree?
      });
  if (!params) return 1;
  try {
    const auto spin = [&stop](auto& driver) {
      ros::AsyncSpinner spinner(1);
      spinner.start();
      // The signal handler only sets `stop`, which nothing can wait on: checked every 50 ms.
      while (!stop.load() && ros::ok()) ros::WallDuration(0.05).sleep();
      spinner.stop();
      driver.stop();
    };
    if (params->task.task == TaskKind::kNavigation) {
      std::optional<DiffDrive> kinematics;
      if (!run.twist) kinematics = makeKinematics(nh, *params, run.action_high);
      NavigationDriver driver(nh, pnh, policy, *params, run, kinematics);
      spin(driver);
    } else {
      RobotDriver driver(nh, pnh, policy, *params, run);
      spin(driver);
    }
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace ppo
}  // namespace jetbot_rl
