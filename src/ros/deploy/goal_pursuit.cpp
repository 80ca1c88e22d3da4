#include "jetbot_rl/ros/deploy/goal_pursuit.h"

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

/// How far `direction` [rad] (odometry frame) lies off the robot's heading, in (-pi, pi].
double offHeading(const nav_msgs::Odometry& odom, double direction) {
  const double heading = tf2::getYaw(odom.pose.pose.orientation);
  return std::atan2(std::sin(direction - heading), std::cos(direction - heading));
}

GoalWatchConfig watchConfig(const GoalPursuitParams& p) {
  GoalWatchConfig c;
  c.timeout = p.goal_timeout;
  c.oscillation_timeout = p.oscillation_timeout;
  c.oscillation_distance = p.oscillation_distance;
  return c;
}

}  // namespace

GoalPursuit::GoalPursuit(ros::NodeHandle& nh, ros::NodeHandle& pnh, const GoalPursuitParams& p,
                         const MoveBaseServerParams& server, double path_lookahead,
                         double footprint_radius, MoveBaseServer::OdomFrame odom_frame,
                         std::function<void()> new_episode, std::function<void()> stop_now)
    : params_(p),
      path_lookahead_(path_lookahead),
      footprint_radius_(footprint_radius),
      map_(nh, p.map_topic),
      server_(
          nh, pnh, server, map_, std::move(odom_frame),
          [this, new_episode] {
            phase_ = Phase::kPlanning;
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
    path_ = std::make_unique<PathFollower>(pnh, f, map_.tf());
    footprint_pub_ = pnh.advertise<geometry_msgs::PolygonStamped>("footprint", 1);
    for (int k = 0; k < 24; ++k) {
      geometry_msgs::Point32 q;
      q.x = static_cast<float>(footprint_radius_ * std::cos(k * M_PI / 12.0));
      q.y = static_cast<float>(footprint_radius_ * std::sin(k * M_PI / 12.0));
      footprint_.polygon.points.push_back(q);
    }
  }
}

double GoalPursuit::now() { return ros::WallTime::now().toSec(); }

std::string GoalPursuit::describe(bool dwa) const {
  std::ostringstream s;
  s << "goals on the action " << server_.actionName() << " and on " << server_.topic();
  if (path_) {
    s << ", plans on " << params_.map_topic << " (~plan; "
      << (dwa                     ? std::string("the DWA follows them")
          : path_lookahead_ > 0.0 ? std::string("the policy observes them")
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
  server_.abort(why);
  if (path_) path_->clear();
  phase_ = Phase::kIdle;
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

void GoalPursuit::publishFootprint(const nav_msgs::Odometry& odom) {
  footprint_.header.frame_id = odom.child_frame_id;
  footprint_.header.stamp = odom.header.stamp;
  footprint_pub_.publish(footprint_);
}

void GoalPursuit::takeMap() {
  if (!path_ || !map_.map() || map_.mapsReceived() == path_map_) return;
  std::string why;
  if (!path_->setMap(*map_.map(), map_.mapFrame(), why)) {
    ROS_WARN("no paths on the map: %s", why.c_str());
  }
  path_map_ = map_.mapsReceived();
}

GoalPursuit::Mode GoalPursuit::step(const nav_msgs::Odometry& odom,
                                    const sensor_msgs::LaserScan* scan, MeasuredState& state,
                                    PlanarTwist& twist) {
  stale_since_.reset();
  if (path_) publishFootprint(odom);
  takeMap();
  if (!server_.started() && (params_.map_topic.empty() || map_.map())) server_.start();
  std::string gone;
  if (server_.goal() && server_.clientGone(gone)) end("aborted: " + gone);
  if (!server_.goal()) {
    phase_ = Phase::kIdle;
    if (path_ && path_->following()) path_->clear();  // a refused goal preempted one
    return Mode::kStand;
  }
  Tick k(odom, scan, state, twist, now());
  if (phase_ == Phase::kPlanning && !plan(k)) return Mode::kStand;
  server_.feedback(odom);
  k.verdict = watch_.check(k.t, k.p, k.why);
  if (k.verdict == GoalWatch::Verdict::kTimedOut) {
    end("aborted: " + k.why);
    return Mode::kStand;
  }
  if (phase_ == Phase::kBackingOff) return backOff(k);
  if (phase_ == Phase::kReplanning) return replan(k);
  Mode lost = Mode::kStand;
  if (!track(k, lost)) return lost;
  if ((k.goal - k.p).norm() <= params_.xy_goal_tolerance) phase_ = Phase::kTurningToHeading;
  if (phase_ == Phase::kTurningToHeading) return turnToHeading(k);
  // Stuck (also turning in place without getting round): recovery.
  if (k.verdict == GoalWatch::Verdict::kStuck) return startRecovery(k.why, k);
  if (phase_ == Phase::kControlling) return control(k);
  return align(k);
}

bool GoalPursuit::plan(Tick& k) {
  recoveries_ = 0;
  watch_.start(k.t, k.p);
  if (path_) {
    const std::string why = server_.goalInMap() ? path_->plan(*server_.goalInMap(), k.odom, k.scan)
                                                : std::string("no map on which to plan a path yet");
    if (!why.empty()) {
      end("no path: " + why);
      return false;
    }
    ROS_INFO("planned a path of %zu points to (%.2f, %.2f) in %s", path_->points().size(),
             server_.goalInMap()->x(), server_.goalInMap()->y(), map_.mapFrame().c_str());
  }
  phase_ = Phase::kAligning;
  return true;
}

bool GoalPursuit::track(Tick& k, Mode& mode) {
  Eigen::Vector2d goal = *server_.goal();
  if (!path_ && server_.goalInMap()) {
    // With a map and no plan the goal stays where it is on the map: map -> odom at each step.
    if (const auto in_odom = map_.fromMap(*server_.goalInMap(), k.odom.header.frame_id)) {
      goal = *in_odom;
    }
  }
  k.state.goal = goal;
  if (path_) {
    const std::string lost = path_->follow(k.odom, k.scan, k.state);
    // A re-plan that found no way (blocked by what the scan sees, or no transform): recovery.
    if (!lost.empty()) {
      mode = startRecovery("no path: " + lost, k);
      return false;
    }
    goal = k.state.goal;                                           // where tf puts it now
    if (path_lookahead_ == 0.0) k.state.goal = k.state.lookahead;  // the carrot
  }
  k.goal = goal;
  return true;
}

GoalPursuit::Mode GoalPursuit::align(Tick& k) {
  const Eigen::Vector2d way = k.state.goal - k.p;  // the carrot, the goal or the path's point ahead
  const Eigen::Vector2d ahead = path_lookahead_ > 0.0 ? k.state.lookahead - k.p : way;
  const double error = offHeading(k.odom, std::atan2(ahead.y(), ahead.x()));
  // A way well off the heading is turned to (after a recovery, any), until nearly ahead.
  const double off = phase_ == Phase::kTurningToWay ? kAlignTo : kAlignFrom;
  if (ahead.norm() > 1e-6 && std::abs(error) > off) {
    phase_ = Phase::kTurningToWay;
    k.twist = turnTowards(error, params_.turn_speed);
    return Mode::kTwist;
  }
  phase_ = Phase::kControlling;
  return control(k);
}

GoalPursuit::Mode GoalPursuit::control(Tick&) { return Mode::kPolicy; }

GoalPursuit::Mode GoalPursuit::turnToHeading(Tick& k) {
  // Only the heading is left (move_base's latch_xy_goal_tolerance): turn in place.
  const double error = offHeading(k.odom, server_.goalYaw());
  if (std::abs(error) <= params_.yaw_goal_tolerance) {
    ROS_INFO("goal (%.2f, %.2f) reached, heading within %.2f rad", k.goal.x(), k.goal.y(),
             std::abs(error));
    server_.succeed();
    if (path_) path_->clear();
    phase_ = Phase::kIdle;
    return Mode::kStand;
  }
  k.twist = turnTowards(error, params_.turn_speed);
  return Mode::kTwist;
}

GoalPursuit::Mode GoalPursuit::startRecovery(const std::string& why, Tick& k) {
  if (recoveries_ >= params_.max_recoveries) {
    end("aborted: " + why + ", after " + std::to_string(recoveries_) +
        " recoveries (max_recoveries)");
    return Mode::kStand;
  }
  if (phase_ != Phase::kBackingOff && phase_ != Phase::kReplanning) {
    // A goal whose position was reached keeps only its heading to turn to (latched).
    after_recovery_ =
        phase_ == Phase::kTurningToHeading ? Phase::kTurningToHeading : Phase::kTurningToWay;
  }
  ++recoveries_;
  ++recoveries_total_;
  ROS_WARN("%s: recovery %d of %d: backing off %.2f m, planning again, turning to the way",
           why.c_str(), recoveries_, params_.max_recoveries, params_.recovery_backoff);
  phase_ = Phase::kBackingOff;
  backing_off_since_ = k.t;
  backoff_from_ = k.p;
  k.twist = {-kBackoffSpeed, 0.0};
  return Mode::kTwist;
}

GoalPursuit::Mode GoalPursuit::backOff(Tick& k) {
  // Bounded in time: a wall behind stops it too.
  const double limit = 3.0 * params_.recovery_backoff / kBackoffSpeed;
  if ((k.p - backoff_from_).norm() < params_.recovery_backoff && k.t - backing_off_since_ < limit) {
    k.twist = {-kBackoffSpeed, 0.0};
    return Mode::kTwist;
  }
  phase_ = Phase::kReplanning;
  plan_due_ = k.t;
  planning_retries_ = 0;
  return replan(k);
}

GoalPursuit::Mode GoalPursuit::replan(Tick& k) {
  // From where the robot stands, around what the scan sees; tried again once per
  // path_replan_period up to max_planning_retries times, then the next recovery.
  k.twist = {0.0, 0.0};
  if (k.t < plan_due_) return Mode::kTwist;
  if (path_) {
    const std::string why = path_->plan(*server_.goalInMap(), k.odom, k.scan);
    if (!why.empty()) {
      if (planning_retries_ < params_.max_planning_retries) {
        ++planning_retries_;
        plan_due_ = k.t + params_.path_replan_period;
        return Mode::kTwist;
      }
      return startRecovery("no path: " + why + " (also after " + std::to_string(planning_retries_) +
                               " planning retries: max_planning_retries)",
                           k);
    }
  }
  // Then turn in place towards the way before the policy drives again (or to the heading).
  watch_.restartProgress(k.t, k.p);
  phase_ = after_recovery_;
  return Mode::kTwist;
}

}  // namespace jetbot_rl
