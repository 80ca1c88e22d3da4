#pragma once

#include <geometry_msgs/PolygonStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <sensor_msgs/LaserScan.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/planning/goal_watch.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/ros/deploy/map_input.h"
#include "jetbot_rl/ros/deploy/move_base_server.h"
#include "jetbot_rl/ros/deploy/path_follower.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/**
 * A navigation goal from its acceptance to its end, as move_base pursues one with a learnt local
 * planner: goals from the MoveBaseServer (the move_base action and RViz's topic), checked on the
 * MapInput's map; with a map, a plan (PathFollower) that a path policy observes and any other
 * policy follows by a carrot (its goal observation a point `carrot_distance` along the plan); a
 * turn in place towards the way first when it lies more than 1 rad off the robot's heading (a
 * reactive policy may freeze on a goal behind it), at each goal and after each recovery; arrival
 * within `xy_goal_tolerance`, then a turn in place to the goal's heading within
 * `yaw_goal_tolerance`; recovery (back off, re-plan around what the scan sees, retried up to
 * `max_planning_retries` times, turn to the way) when the robot makes no progress or a re-plan
 * finds no way, ABORTED when recoveries run out, the goal times out, the inputs stay stale for
 * `controller_patience` or the goal's client disconnects. The goal's phases are Phase, each
 * stepped by its own function. With plans, the footprint planned for is published on
 * ~footprint at each step, in the robot's frame with the odometry's stamp.
 */
class GoalPursuit {
 public:
  /// What the robot does this control step.
  enum class Mode {
    kStand,   ///< No goal: stop (quiet: the driver sends one zero Twist).
    kPolicy,  ///< The policy acts on the measured state (its goal and path filled in).
    kTwist,   ///< A fixed twist (turning to the heading, backing off).
  };

  /// Where a goal is (move_base's PLANNING, CONTROLLING and CLEARING, told apart further).
  enum class Phase {
    kIdle,              ///< No goal.
    kPlanning,          ///< A goal just came: it is planned for at the next step.
    kAligning,          ///< Checking the way's bearing: more than 1 rad off turns to it first.
    kTurningToWay,      ///< Turning in place towards the way (until within 0.3 rad).
    kControlling,       ///< The policy drives.
    kTurningToHeading,  ///< Within xy_goal_tolerance (latched): turning to the goal's heading.
    kBackingOff,        ///< A recovery's first part: backing off recovery_backoff.
    kReplanning,        ///< A recovery's second part: planning again, standing (retried).
  };

  /// `path_lookahead` [m]: the policy observes a path with it (0: it does not);
  /// `footprint_radius` [m] plans for the robot; `new_episode` is called when a goal starts
  /// (the policy's memory starts over) and `stop_now` when one is canceled.
  GoalPursuit(ros::NodeHandle& nh, ros::NodeHandle& pnh, const GoalPursuitParams& p,
              const MoveBaseServerParams& server, double path_lookahead, double footprint_radius,
              MoveBaseServer::OdomFrame odom_frame, std::function<void()> new_episode,
              std::function<void()> stop_now);

  /// True when goals are planned on the map: a policy that observes a path
  /// (`path_lookahead` > 0 [m]), or any other with a map and a carrot.
  static bool plansPaths(const GoalPursuitParams& p, double path_lookahead) {
    return path_lookahead > 0.0 || (!p.map_topic.empty() && p.carrot_distance > 0.0);
  }
  /// One control step on fresh inputs: fills `state`'s goal (and path) for kPolicy, or `twist`.
  Mode step(const nav_msgs::Odometry& odom, const sensor_msgs::LaserScan* scan,
            MeasuredState& state, PlanarTwist& twist);
  /// One control step on stale inputs (`what` names them): ABORTED after controller_patience.
  void stale(const std::string& what);
  /// True while a goal is pursued.
  bool active() const { return server_.goal().has_value(); }
  /// The goal's phase.
  Phase phase() const { return phase_; }
  /// With a plan: the plan and its point `distance` [m] past the robot, in the odometry frame of
  /// the last step (PathFollower::way()); false without one (the way is the straight line).
  bool way(double distance, std::vector<Eigen::Vector2d>& points, Eigen::Vector2d& ahead) const {
    return path_ && path_->way(distance, points, ahead);
  }
  /// The goal topic and plans (followed by the DWA with `dwa`), for the start-up line.
  std::string describe(bool dwa = false) const;
  /// What the driver's status tells: the goal, plans, re-plans and recoveries.
  void addStatus(const std::function<void(const std::string&, const std::string&)>& add) const;

 private:
  /// One step's inputs and outputs, handed from phase to phase.
  struct Tick {
    Tick(const nav_msgs::Odometry& o, const sensor_msgs::LaserScan* s, MeasuredState& st,
         PlanarTwist& tw, double time)
        : odom(o), scan(s), state(st), twist(tw), p(st.root.position.head<2>()), t(time) {}
    const nav_msgs::Odometry& odom;
    const sensor_msgs::LaserScan* scan;
    MeasuredState& state;
    PlanarTwist& twist;
    Eigen::Vector2d p;             // the robot in the odometry frame [m]
    double t;                      // [s, wall]
    Eigen::Vector2d goal{0, 0};    // the goal in the odometry frame, where tf puts it now [m]
    GoalWatch::Verdict verdict{};  // the watch's at this step
    std::string why;               // ... and why
  };

  static double now();
  void end(const std::string& why);
  /// The circle the plans keep clear, in the robot's frame with `odom`'s stamp (RViz's Polygon
  /// display places it through tf at that stamp).
  void publishFootprint(const nav_msgs::Odometry& odom);
  /// Hands a new map to the path follower.
  void takeMap();
  /// kPlanning: starts the goal and plans for it; false when it ended.
  bool plan(Tick& k);
  /// The goal (and with a plan the carrot or path) into `k.state` for the phases that track it;
  /// false when a re-plan found no way (a recovery started).
  bool track(Tick& k, Mode& mode);
  /// kAligning and kTurningToWay: a turn towards the way, or on to kControlling.
  Mode align(Tick& k);
  /// kControlling: the policy drives.
  Mode control(Tick& k);
  /// kTurningToHeading: a turn in place to the goal's heading, then SUCCEEDED.
  Mode turnToHeading(Tick& k);
  /// A recovery for `why` (stuck, no path any more): kBackingOff, or ABORTED after
  /// max_recoveries.
  Mode startRecovery(const std::string& why, Tick& k);
  /// kBackingOff: backing off (bounded in time), then kReplanning.
  Mode backOff(Tick& k);
  /// kReplanning: planning again from where the robot stands (retried), then kTurningToWay (or
  /// back to kTurningToHeading).
  Mode replan(Tick& k);

  GoalPursuitParams params_;
  double path_lookahead_, footprint_radius_;
  ros::Publisher footprint_pub_;             // with plans
  geometry_msgs::PolygonStamped footprint_;  // its circle in the robot's frame
  MapInput map_;
  MoveBaseServer server_;
  std::unique_ptr<PathFollower> path_;  // with a map: a path policy or a carrot
  int path_map_ = 0;                    // the map the follower plans on
  GoalWatch watch_;
  Phase phase_ = Phase::kIdle;
  Phase after_recovery_ = Phase::kTurningToWay;  // where a recovery's end returns to
  int recoveries_ = 0, recoveries_total_ = 0;
  double backing_off_since_ = 0.0;  // kBackingOff: since [s]
  Eigen::Vector2d backoff_from_ = Eigen::Vector2d::Zero();
  double plan_due_ = 0.0;              // kReplanning: plans again at this time [s]
  int planning_retries_ = 0;           // ... after this many failed plans
  std::optional<double> stale_since_;  // [s]
};

}  // namespace jetbot_rl
