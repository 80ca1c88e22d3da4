#include "jetbot_rl/ros/deploy/deploy_driver.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/console.h>
#include <ros/this_node.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/common/private_topic.h"
#include "jetbot_rl/ros/common/publication_flush.h"
#include "jetbot_rl/tasks/command_task.h"

namespace jetbot_rl {
namespace {

/// "" for odometry the observer can use, else why it is dropped.
std::string checkOdometry(const nav_msgs::Odometry& m) {
  const auto& p = m.pose.pose.position;
  const auto& q = m.pose.pose.orientation;
  const auto& v = m.twist.twist.linear;
  const auto& w = m.twist.twist.angular;
  bool usable = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w > 1e-12;
  for (double x : {p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, w.x, w.y, w.z}) {
    usable = usable && std::isfinite(x);
  }
  return usable ? "" : "with a non-finite value or a zero quaternion";
}

}  // namespace

PolicyRun policyRunOf(const ppo::Policy& policy, const std::string& checkpoint) {
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
  run.path_lookahead = spec.observer.path_lookahead;
  run.twist = actsByTwist(spec);
  run.action_high.assign(spec.action_high.begin(), spec.action_high.end());
  run.checkpoint = checkpoint;
  return run;
}

std::unique_ptr<TaskObserver> observerOf(const BatchSpec& trained, double goal_radius,
                                         const std::string& checkpoint) {
  BatchSpec spec = trained;
  spec.observer.goal_radius = goal_radius;
  std::unique_ptr<TaskObserver> observer = makeObserver(spec);
  const std::vector<std::string> names = observer->observationNames();
  if (names != trained.observation_names) {
    throw ConfigError("the " + trained.task + " task observes " + listText(names) +
                      "; the policy of " + checkpoint + " was trained on " +
                      listText(trained.observation_names));
  }
  return observer;
}

DeployDriver::DeployDriver(ros::NodeHandle& nh, ros::NodeHandle& pnh, ppo::Policy& policy,
                           const TaskObserver& observer, const DeployParams& p,
                           const PolicyRun& run, const std::optional<DiffDrive>& kinematics)
    : policy_(policy),
      observer_(observer),
      run_(run),
      trained_(policy.meta().spec.observer),
      kinematics_(kinematics),
      drops_(nh, ros::this_node::getName() + ": deploy input", "dropped input"),
      odom_(nh, p.driver.odom_topic, "odometry", p.driver.odom_timeout, checkOdometry, drops_) {
  if (!run.twist && !kinematics_) throw Error("DeployDriver: wheel actions need kinematics");
  if (observer.scanBeams() != static_cast<int>(trained_.scan_beam_angles.size())) {
    throw ConfigError("the policy observes " + std::to_string(observer.scanBeams()) +
                      " scan beams; " + std::to_string(trained_.scan_beam_angles.size()) +
                      " are known");
  }
  if (p.local.planner == LocalPlanner::kDwa) {  // checked before the scan, goals and timers
    if (!observer.hasGoal() || observer.scanBeams() == 0) {
      throwInvalid("local_planner", "dwa",
                   "drives towards goals on the robot's scan: the checkpoint's task '" +
                       policy.meta().spec.task + "' has " +
                       (observer.hasGoal() ? "no scan" : "no goals"));
    }
    dwa_ = std::make_unique<DwaLocalPlanner>(p.local.dwa, p.pursuit.footprint_radius);
  }
  last_action_.assign(static_cast<std::size_t>(policy.actionDim()), 0.0f);
  cmd_vel_pub_ = nh.advertise<geometry_msgs::Twist>(p.driver.cmd_vel_topic, 10);
  status_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  std::string inputs = odom_.topic();
  if (observer.scanBeams() > 0) {
    scan_ = std::make_unique<FreshInput<sensor_msgs::LaserScan>>(
        nh, p.driver.scan_topic, "scan", p.driver.scan_timeout,
        [this](const sensor_msgs::LaserScan& scan) {
          std::string error;
          return resampleScan(scan, trained_, ranges_, error) ? "" : "refused: " + error;
        },
        drops_);
    inputs += ", " + scan_->topic();
  }
  if (policy.observesImage()) {
    image_ = std::make_unique<ImageInput>(nh, p.driver.image_topic, p.driver.image_transport,
                                          policy.imageWidth(), policy.imageHeight(),
                                          p.driver.image_timeout, drops_);
    inputs += ", " + image_->describe();
  }
  if (observer.hasGoal()) {
    pursuit_ = std::make_unique<GoalPursuit>(
        nh, pnh, p.pursuit, p.server, run.path_lookahead, p.pursuit.footprint_radius,
        [this] { return odom_.latest() ? odom_.latest()->header.frame_id : std::string(); },
        [this] { policy_.resetMemory(); },  // each goal is an episode
        [this] {                            // a cancel stops the robot at once
          stand("goal canceled", false);
          publish(geometry_msgs::Twist(), true);
        });
    inputs += " and " + pursuit_->describe(dwa_ != nullptr);
  }
  if (observer.takesCommand()) {
    command_sub_ = nh.subscribe(resolvePrivateTopic(pnh, p.driver.command_topic), 10,
                                &DeployDriver::onCommand, this);
    inputs += " and commands on " + command_sub_.getTopic();
  }
  timer_ =
      nh.createWallTimer(ros::WallDuration(1.0 / run.control_rate), &DeployDriver::onTick, this);
  status_timer_ = nh.createWallTimer(ros::WallDuration(1.0), &DeployDriver::onStatus, this);
  std::ostringstream s;
  s << "deploying " << run.checkpoint << ": " << inputs << " -> "
    << (dwa_ ? "the dynamic window approach (local_planner dwa, max_vel_x " +
                   std::to_string(p.local.dwa.max_vel_x) + " m/s; the policy does not act)"
             : std::string("policy") + (policy.hasMemory() ? " (with memory)" : ""))
    << " -> " << cmd_vel_pub_.getTopic() << " at " << run.control_rate << " Hz ("
    << (run.twist ? "twist" : "wheel") << " actions"
    << (kinematics_ ? ", " + kinematics_->describe() : std::string()) << "; the checkpoint's)";
  if (scan_) {
    s << "; " << trained_.scan_beam_angles.size() << " beams over ["
      << trained_.scan_beam_angles.front() << ", " << trained_.scan_beam_angles.back()
      << "] rad, range " << listText(trained_.scan_range) << " m";
    if (trained_.scan_source == "camera_depth" && trained_.scan_heights.size() == 2) {
      s << " (trained on scans made from a depth camera's points " << trained_.scan_heights.at(0)
        << " to " << trained_.scan_heights.at(1)
        << " m above the ground: give it such a LaserScan, e.g. jetbot_depth_scan's from the "
           "robot's depth camera, deploy.launch depth_image:=TOPIC)";
    }
  }
  if (trained_.speed_limit_distances.size() == 2 && !dwa_) {
    s << "; forward speed limited as in training: 0 within " << trained_.speed_limit_distances[0]
      << " m ahead of the front, full beyond " << trained_.speed_limit_distances[1] << " m";
  }
  ROS_INFO("%s", s.str().c_str());
}

void DeployDriver::stop() {
  timer_.stop();
  status_timer_.stop();
  cmd_vel_pub_.publish(geometry_msgs::Twist());
  flushPublications(0.5);
}

void DeployDriver::onCommand(const geometry_msgs::Vector3::ConstPtr& msg) {
  try {
    command_ = unitCommand({msg->x, msg->y}, "command on " + command_sub_.getTopic());
    policy_.resetMemory();  // a new command starts a new episode, as in training
  } catch (const InputError& e) {
    ROS_WARN_THROTTLE(1.0, "command ignored: %s", e.what());
  }
}

void DeployDriver::stand(const std::string& why, bool fresh_start) {
  standing_ = why;
  std::fill(last_action_.begin(), last_action_.end(), 0.0f);
  if (fresh_start) policy_.resetMemory();
}

void DeployDriver::publish(const geometry_msgs::Twist& twist, bool stop) {
  if (pursuit_ && stop && stopped_) return;  // quiet: one zero Twist per stop
  stopped_ = stop;
  cmd_vel_pub_.publish(twist);
}

void DeployDriver::onTick(const ros::WallTimerEvent&) {
  const bool stale_odom = !odom_.fresh();
  const bool stale_scan = scan_ && !scan_->fresh();
  const bool stale_image = image_ && !image_->fresh();
  if (stale_odom || stale_scan || stale_image) {
    const std::string what = stale_odom   ? "odometry on " + odom_.topic()
                             : stale_scan ? "scan on " + scan_->topic()
                                          : "image on " + image_->topic();
    ROS_WARN_THROTTLE(2.0, "no fresh %s: the robot stands", what.c_str());
    stand("no fresh " + what, true);  // its memory starts over with the next drive
    if (pursuit_) pursuit_->stale(what);
    publish(geometry_msgs::Twist(), true);
    return;
  }
  MeasuredState state;
  state.root = rootStateOf(*odom_.latest());
  if (scan_) {
    std::string error;
    resampleScan(*scan_->latest(), trained_, ranges_, error);  // it took it: it covers them
    state.scan = ranges_.data();
  }
  state.command = command_;
  state.last_action = last_action_.data();
  if (pursuit_) {
    PlanarTwist fixed;
    switch (
        pursuit_->step(*odom_.latest(), scan_ ? scan_->latest().get() : nullptr, state, fixed)) {
      case GoalPursuit::Mode::kStand:
        stand("no goal", false);
        publish(geometry_msgs::Twist(), true);
        return;
      case GoalPursuit::Mode::kTwist: {
        standing_.clear();
        std::fill(last_action_.begin(), last_action_.end(), 0.0f);
        geometry_msgs::Twist twist;
        twist.linear.x = fixed.linear;
        twist.angular.z = fixed.angular;
        publish(twist, false);
        return;
      }
      case GoalPursuit::Mode::kPolicy:
        break;
    }
  }
  standing_.clear();
  publish(dwa_ ? dwaStep(state) : act(state), false);
}

geometry_msgs::Twist DeployDriver::dwaStep(const MeasuredState& state) {
  Eigen::Vector2d local_goal = state.goal;
  if (!pursuit_->way(dwa_->config().local_goal_distance, way_, local_goal)) way_.clear();
  const PlanarTwist command = dwa_->step(state, *scan_->latest(), way_, local_goal);
  geometry_msgs::Twist twist;
  twist.linear.x = command.linear;
  twist.angular.z = command.angular;
  return twist;
}

geometry_msgs::Twist DeployDriver::act(const MeasuredState& state) {
  obs_.resize(static_cast<std::size_t>(policy_.obsDim()));
  observer_.observe(state, obs_.data());
  if (image_) {
    policy_.act(obs_, image_->rgb(), 1, actions_);
  } else {
    policy_.act(obs_, 1, actions_);
  }
  // The limit it was trained behind, on the robot's own scan (a twist policy: the env refuses
  // it for wheel actions); the capped v is the last action it observes, as in training.
  if (run_.twist) actions_[0] = std::min(actions_[0], static_cast<float>(speedCap(actions_[0])));
  std::copy(actions_.begin(), actions_.begin() + last_action_.size(), last_action_.begin());
  geometry_msgs::Twist twist;
  if (run_.twist) {
    twist.linear.x = actions_[0];
    twist.angular.z = actions_[1];
  } else {
    const PlanarTwist body = kinematics_->bodyTwist({actions_[0], actions_[1]});
    twist.linear.x = body.linear;
    twist.angular.z = body.angular;
  }
  return twist;
}

double DeployDriver::speedCap(double v_max) {
  if (trained_.speed_limit_path.size() != 3 || !scan_ || !scan_->latest()) return v_max;
  const sensor_msgs::LaserScan& scan = *scan_->latest();
  const ScanView view{scan.ranges.data(), static_cast<int>(scan.ranges.size()), scan.angle_min,
                      scan.angle_increment};
  if (!speed_limit_ || !speed_limit_->fits(view, scan.range_min)) {
    const std::vector<double>& path = trained_.speed_limit_path;
    const std::vector<double>& d = trained_.speed_limit_distances;
    speed_limit_ =
        std::make_unique<SpeedLimit>(SpeedLimitSpec{path[0], path[1], path[2], d[0], d[1]},
                                     view.samples, view.angle_min, view.increment, scan.range_min);
  }
  clear_ahead_ = speed_limit_->clearAhead(view.ranges);
  return speed_limit_->capAt(clear_ahead_, v_max);
}

void DeployDriver::onStatus(const ros::WallTimerEvent&) {
  diagnostic_msgs::DiagnosticStatus status;
  status.name = ros::this_node::getName() + ": deploy";
  const bool stale = standing_.rfind("no fresh", 0) == 0;
  status.level =
      stale ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
  status.message = standing_.empty() ? "driving" : "standing: " + standing_;
  const auto add = [&status](const std::string& key, const std::string& value) {
    diagnostic_msgs::KeyValue kv;
    kv.key = key;
    kv.value = value;
    status.values.push_back(kv);
  };
  add("odometry age [s]", std::to_string(odom_.age()));
  if (scan_) add("scan age [s]", std::to_string(scan_->age()));
  if (image_) add("image age [s]", std::to_string(image_->age()));
  add("dropped input", std::to_string(drops_.count()));
  if (pursuit_) pursuit_->addStatus(add);
  if (speed_limit_) add("speed limit: clear ahead [m]", std::to_string(clear_ahead_));
  if (dwa_) {
    add("local planner", "dwa");
    add("dwa steps without a clear trajectory", std::to_string(dwa_->blockedSteps()));
  }
  diagnostic_msgs::DiagnosticArray msg;
  msg.header.stamp = ros::Time::now();
  msg.status.push_back(std::move(status));
  status_pub_.publish(msg);
}

}  // namespace jetbot_rl
