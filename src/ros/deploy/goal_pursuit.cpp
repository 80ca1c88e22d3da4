#include "jetbot_rl/ros/deploy/goal_pursuit.h"

#include <geometry_msgs/PolygonStamped.h>
#include <ros/console.h>
#include <tf2/utils.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace {

constexpr double kBackoffSpeed = 0.1;  // a recovery backs off at this [m/s]
constexpr double kAlignFrom = 1.0;     // a way this far off the heading is turned to first [rad]
constexpr double kAlignTo = 0.3;       // ... until it is this far off [rad]
constexpr double kTurnGain = 4.0;      // a turn in place slows down at this rate [1/s]

/// A turn in place towards `error` [rad] off, at up to `top` [rad/s].
PlanarTwist turnTowards(double error, double top) {
  return {0.0, std::copysign(std::clamp(kTurnGain * std::abs(error), 0.2, top), error)};
}

GoalWatchConfig watchConfig(const DeployParams& p) {
  GoalWatchConfig c;
  c.timeout = p.goal_timeout;
  c.oscillation_timeout = p.oscillation_timeout;
  c.oscillation_distance = p.oscillation_distance;
  return c;
}

}  // namespace

GoalPursuit::GoalPursuit(ros::NodeHandle& nh, ros::NodeHandle& pnh, const DeployParams& p,
                         double path_lookahead, double footprint_radius,
                         GoalInput::OdomFrame odom_frame, std::function<void()> new_episode,
                         std::function<void()> stop_now)
    : params_(p),
      path_lookahead_(path_lookahead),
      footprint_radius_(footprint_radius),
      goals_(
          nh, pnh, p.action_name, p.goal_topic, p.outcome_topic, p.map_topic, std::move(odom_frame),
          [this, new_episode] {
            new_goal_ = true;
            new_episode();
          },
          [this, stop_now] {
            if (path_) path_->clear();  // a canceled goal's plan goes from RViz too
            stop_now();
          }),
      watch_(watchConfig(p)) {
  if (path_lookahead > 0.0 && p.map_topic.empty()) {
    throwInvalid("map_topic", "''",
                 "the policy follows a global path, which is planned on a map: name its topic");
  }
  if (plansPaths(p, path_lookahead)) {
    PathFollowing f;
    f.planner.robot_radius = footprint_radius;
    f.planner.clearance = p.path_clearance;
    f.planner.clearance_cost = p.path_clearance_cost;
    f.lookahead = path_lookahead > 0.0 ? path_lookahead : p.carrot_distance;
    f.replan_distance = p.path_replan_distance;
    f.blocked_distance = p.path_blocked_distance;
    f.replan_period = p.path_replan_period;
    path_ = std::make_unique<PathFollower>(pnh, f, goals_.tf());
    footprint_pub_ = pnh.advertise<geometry_msgs::PolygonStamped>("footprint", 1, true);
  }
}

double GoalPursuit::now() { return ros::WallTime::now().toSec(); }

std::string GoalPursuit::describe() const {
  std::ostringstream s;
  s << "goals on the action " << goals_.actionName() << " and on " << goals_.topic();
  if (path_) {
    s << ", plans on " << params_.map_topic << " (~plan; "
      << (path_lookahead_ > 0.0 ? "the policy observes them"
                                : "the policy's goal a carrot " +
                                      std::to_string(params_.carrot_distance) + " m along them")
      << ")";
  }
  return s.str();
}

void GoalPursuit::addStatus(
    const std::function<void(const std::string&, const std::string&)>& add) const {
  add("goal", active() ? "active" : "none");
  if (path_) {
    add("paths planned", std::to_string(path_->plans()));
    add("re-plans", std::to_string(path_->replans()));
  }
  add("recoveries", std::to_string(recoveries_total_));
}

void GoalPursuit::end(const std::string& why) {
  goals_.abort(why);
  if (path_) path_->clear();
  backing_off_since_.reset();
  plan_due_.reset();
}

void GoalPursuit::stale(const std::string& what) {
  if (!active()) return;
  const double t = now();
  if (!stale_since_) stale_since_ = t;
  if (t - *stale_since_ > params_.controller_patience) {
    std::ostringstream s;
    s << "aborted: stale inputs: no fresh " << what << " for " << params_.controller_patience
      << " s (controller_patience)";
    end(s.str());
  }
}

bool GoalPursuit::planNewGoal(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan) {
  const std::string why = goals_.goalInMap() ? path_->plan(*goals_.goalInMap(), odom, scan)
                                             : std::string("no map on which to plan a path yet");
  if (!why.empty()) {
    end("no path: " + why);
    return false;
  }
  ROS_INFO("planned a path of %zu points to (%.2f, %.2f) in %s", path_->points().size(),
           goals_.goalInMap()->x(), goals_.goalInMap()->y(), goals_.mapFrame().c_str());
  return true;
}

GoalPursuit::Mode GoalPursuit::step(const nav_msgs::Odometry& odom,
                                    const sensor_msgs::LaserScan* scan, MeasuredState& state,
                                    PlanarTwist& twist) {
  stale_since_.reset();
  if (path_ && !footprint_sent_) {
    // The circle the plans keep clear, in the robot's frame (RViz's Polygon display).
    geometry_msgs::PolygonStamped footprint;
    footprint.header.frame_id = odom.child_frame_id;
    for (int k = 0; k < 24; ++k) {
      geometry_msgs::Point32 q;
      q.x = static_cast<float>(footprint_radius_ * std::cos(k * M_PI / 12.0));
      q.y = static_cast<float>(footprint_radius_ * std::sin(k * M_PI / 12.0));
      footprint.polygon.points.push_back(q);
    }
    footprint_pub_.publish(footprint);
    footprint_sent_ = true;
  }
  if (path_ && goals_.map() && goals_.mapsReceived() != path_map_) {
    std::string why;
    if (!path_->setMap(*goals_.map(), goals_.mapFrame(), why)) {
      ROS_WARN("no paths on the map: %s", why.c_str());
    }
    path_map_ = goals_.mapsReceived();
  }
  if (!goals_.started() && (params_.map_topic.empty() || goals_.map())) goals_.start();
  std::string gone;
  if (goals_.goal() && goals_.clientGone(gone)) end("aborted: " + gone);
  if (!goals_.goal()) {
    if (path_ && path_->following()) path_->clear();  // a refused goal preempted one
    return Mode::kStand;
  }
  const Eigen::Vector2d p = state.root.position.head<2>();
  const double t = now();
  if (new_goal_) {
    new_goal_ = false;
    xy_reached_ = false;
    recoveries_ = 0;
    backing_off_since_.reset();
    plan_due_.reset();
    watch_.start(t, p);
    if (path_ && !planNewGoal(odom, scan)) return Mode::kStand;
    aligning_ = true;
    align_turning_ = align_fully_ = false;
  }
  goals_.feedback(odom);
  std::string why;
  const GoalWatch::Verdict verdict = watch_.check(t, p, why);
  if (verdict == GoalWatch::Verdict::kTimedOut) {
    end("aborted: " + why);
    return Mode::kStand;
  }
  if (backing_off_since_ || plan_due_) return recover(odom, scan, p, t, twist);
  Eigen::Vector2d goal = *goals_.goal();
  if (!path_ && goals_.goalInMap()) {
    // With a map and no plan the goal stays where it is on the map: map -> odom at each step.
    if (const auto in_odom = goals_.fromMap(*goals_.goalInMap(), odom.header.frame_id)) {
      goal = *in_odom;
    }
  }
  state.goal = goal;
  if (path_) {
    const std::string lost = path_->follow(odom, scan, state);
    // A re-plan that found no way (blocked by what the scan sees, or no transform): recovery.
    if (!lost.empty()) return startRecovery("no path: " + lost, p, t, twist);
    goal = state.goal;                                         // where tf puts it now
    if (path_lookahead_ == 0.0) state.goal = state.lookahead;  // the carrot
  }
  if (!xy_reached_ && (goal - p).norm() <= params_.xy_goal_tolerance) xy_reached_ = true;
  const double heading = tf2::getYaw(odom.pose.pose.orientation);
  const auto offHeading = [heading](double direction) {
    return std::atan2(std::sin(direction - heading), std::cos(direction - heading));
  };
  if (xy_reached_) {
    // Only the heading is left (move_base's latch_xy_goal_tolerance): turn in place.
    const double error = offHeading(goals_.goalYaw());
    if (std::abs(error) <= params_.yaw_goal_tolerance) {
      ROS_INFO("goal (%.2f, %.2f) reached, heading within %.2f rad", goal.x(), goal.y(),
               std::abs(error));
      goals_.succeed();
      if (path_) path_->clear();
      return Mode::kStand;
    }
    twist = turnTowards(error, params_.turn_speed);
    return Mode::kTwist;
  }
  // Stuck (also turning in place without getting round): recovery.
  if (verdict == GoalWatch::Verdict::kStuck) return startRecovery(why, p, t, twist);
  if (aligning_) {
    const Eigen::Vector2d way = state.goal - p;  // the carrot, the goal or the path's point ahead
    const Eigen::Vector2d ahead = path_lookahead_ > 0.0 ? state.lookahead - p : way;
    const double error = offHeading(std::atan2(ahead.y(), ahead.x()));
    // A way well off the heading is turned to (after a recovery, any), until nearly ahead.
    const bool turn = align_turning_ || align_fully_;
    if (ahead.norm() > 1e-6 && std::abs(error) > (turn ? kAlignTo : kAlignFrom)) {
      align_turning_ = true;
      twist = turnTowards(error, params_.turn_speed);
      return Mode::kTwist;
    }
    aligning_ = align_turning_ = align_fully_ = false;
  }
  return Mode::kPolicy;
}

GoalPursuit::Mode GoalPursuit::startRecovery(const std::string& why, const Eigen::Vector2d& p,
                                             double t, PlanarTwist& twist) {
  if (recoveries_ >= params_.max_recoveries) {
    end("aborted: " + why + ", after " + std::to_string(recoveries_) +
        " recoveries (max_recoveries)");
    return Mode::kStand;
  }
  ++recoveries_;
  ++recoveries_total_;
  ROS_WARN("%s: recovery %d of %d: backing off %.2f m, planning again, turning to the way",
           why.c_str(), recoveries_, params_.max_recoveries, params_.recovery_backoff);
  backing_off_since_ = t;
  backoff_from_ = p;
  twist = {-kBackoffSpeed, 0.0};
  return Mode::kTwist;
}

GoalPursuit::Mode GoalPursuit::recover(const nav_msgs::Odometry& odom,
                                       const sensor_msgs::LaserScan* scan, const Eigen::Vector2d& p,
                                       double t, PlanarTwist& twist) {
  // 1. Back off (bounded in time: a wall behind stops it too).
  if (backing_off_since_) {
    const double limit = 3.0 * params_.recovery_backoff / kBackoffSpeed;
    if ((p - backoff_from_).norm() < params_.recovery_backoff && t - *backing_off_since_ < limit) {
      twist = {-kBackoffSpeed, 0.0};
      return Mode::kTwist;
    }
    backing_off_since_.reset();
    plan_due_ = t;
    planning_retries_ = 0;
  }
  // 2. Plan again from there around what the scan sees, standing; tried again once per
  //    path_replan_period up to max_planning_retries times, then the next recovery.
  twist = {0.0, 0.0};
  if (t < *plan_due_) return Mode::kTwist;
  if (path_) {
    const std::string why = path_->plan(*goals_.goalInMap(), odom, scan);
    if (!why.empty()) {
      if (planning_retries_ < params_.max_planning_retries) {
        ++planning_retries_;
        plan_due_ = t + params_.path_replan_period;
        return Mode::kTwist;
      }
      plan_due_.reset();
      return startRecovery("no path: " + why + " (also after " + std::to_string(planning_retries_) +
                               " planning retries: max_planning_retries)",
                           p, t, twist);
    }
  }
  // 3. Then turn in place towards the way before the policy drives again.
  plan_due_.reset();
  watch_.restartProgress(t, p);
  aligning_ = align_fully_ = true;
  align_turning_ = false;
  return Mode::kTwist;
}

}  // namespace jetbot_rl
