#pragma once

#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/planning/dwa_planner.h"
#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {

/// The driver's parameters (DeployDriver, runDeploy): the checkpoint, the robot's topics and
/// kinematics, the scan's beams, the camera.
struct DriverParams {
  std::string checkpoint;  ///< Checkpoint file, or a run directory (its checkpoints/best.pt).
  std::string task;        ///< The task the policy was trained on; "": the checkpoint's.
  std::string odom_topic = "odom";                ///< nav_msgs/Odometry of the robot.
  std::string cmd_vel_topic = "/jetbot/cmd_vel";  ///< geometry_msgs/Twist the driver takes.
  std::string command_topic = "~command";         ///< geometry_msgs/Vector3: command task's (x, y).
  double odom_timeout = 0.5;                      ///< Older odometry stops the robot [s, wall].
  /// Wheel radius [m] for wheel targets -> Twist: the driver's, which turns the Twist back into
  /// wheel speeds (stock Jetbot: 0.0603 m wheels); 0: the checkpoint's (the trained robot's),
  /// robot_description's where it has none.
  double wheel_radius = 0.0;
  /// Wheel separation [m], the driver's (stock Jetbot: 0.1016); 0: as wheel_radius.
  double wheel_separation = 0.0;
  /// The wheel joints in the policy's action order (used with robot_description).
  std::vector<std::string> dof_names{"left_wheel_joint", "right_wheel_joint"};
  std::string scan_topic = "scan";               ///< sensor_msgs/LaserScan of the robot.
  double scan_timeout = 0.5;                     ///< An older scan stops the robot [s, wall].
  std::string image_topic = "camera/image_raw";  ///< sensor_msgs/Image of the robot's camera.
  std::string image_transport = "raw";           ///< The image_transport its images come by.
  double image_timeout = 0.5;                    ///< An older image stops the robot [s, wall].
};

/// The move_base action server's parameters (MoveBaseServer).
struct MoveBaseServerParams {
  std::string goal_topic = "/move_base_simple/goal";  ///< geometry_msgs/PoseStamped (RViz).
  std::string outcome_topic = "~outcome";             ///< std_msgs/String: what became of a goal.
  std::string action_name = "move_base";              ///< The move_base_msgs/MoveBaseAction server.
};

/// A goal's pursuit's parameters (GoalPursuit, its MapInput and PathFollower): tolerances,
/// recoveries, the map and the paths planned on it.
struct GoalPursuitParams {
  /// A goal is reached within this of the robot's origin [m]; 0: the checkpoint's goal_radius.
  double xy_goal_tolerance = 0.0;
  double yaw_goal_tolerance = 0.1;   ///< ... then turned to within this of its heading [rad].
  double turn_speed = 3.0;           ///< A turn in place's top rate [rad/s].
  double goal_timeout = 120.0;       ///< A goal not reached by then is ABORTED [s, wall]; 0: never.
  double controller_patience = 3.0;  ///< Inputs stale this long ABORT the goal [s, wall].
  double oscillation_timeout = 10.0;  ///< No progress this long is stuck [s, wall]; 0: never.
  double oscillation_distance = 0.2;  ///< Moving this far is progress [m].
  int max_recoveries = 2;             ///< Recoveries before a stuck goal is ABORTED.
  double recovery_backoff = 0.15;     ///< A recovery backs off this far [m].
  int max_planning_retries = 2;       ///< A recovery's failed plan is tried again this often.
  double carrot_distance = 0.6;  ///< With a map, a policy without a path: its goal this far along.
  std::string map_topic;  ///< nav_msgs/OccupancyGrid: goals off its free cells refused; "": none.
  // ---- a policy that follows a global path (trained with nav/path) ----
  // The next three: 0 (footprint), < 0 (clearances): the checkpoint's.
  double footprint_radius = 0.0;      ///< The robot's footprint [m].
  double path_clearance = -1.0;       ///< Paths keep this beyond the footprint where there is room.
  double path_clearance_cost = -1.0;  ///< A cell at the footprint's cost beyond its length.
  double path_replan_distance = 0.5;  ///< Farther from the path re-plans [m].
  double path_blocked_distance = 1.0;  ///< The path ahead checked against the scan [m]; 0: off.
  double path_replan_period = 1.0;     ///< At most one re-plan per this [s, wall].
};

/// What drives the deploy node's robot towards a goal (move_base's base_local_planner).
enum class LocalPlanner {
  kPolicy,  ///< The checkpoint's policy.
  kDwa,     ///< The dynamic window approach (DwaPlanner), the navigation benchmark's `dwa` rows.
};

inline const EnumNameList<LocalPlanner>& enumNames(LocalPlanner) {
  static const EnumNameList<LocalPlanner> names{{LocalPlanner::kPolicy, "policy"},
                                                {LocalPlanner::kDwa, "dwa"}};
  return names;
}

/// What drives a navigation robot towards its goals (DwaLocalPlanner for the baseline).
struct LocalPlannerParams {
  LocalPlanner planner = LocalPlanner::kPolicy;  ///< The policy, or the DWA baseline.
  DwaConfig dwa;  ///< The baseline's; max_vel_x the policy's top speed unless given.
};

/// Private parameters of jetbot_deploy_node: a trained policy driving a robot (odometry, and a
/// scan and goals for navigation, in; cmd_vel out). Defaults suit the stock Jetbot's ROS 2 driver
/// (dusty-nv/jetbot_ros). What the policy was trained with (task, control rate, action bounds,
/// whether the actions are wheel targets or a twist, the observed scan beams) comes from the
/// checkpoint, and so do the trained robot's geometry, goal radius and path clearance unless given
/// (takeTrainedSettings()); these are the robot's side only (no simulation parameter, no reward).
/// Grouped by the component that takes them; one flat list of parameters (visitFields), read,
/// validated and echoed once at start-up.
struct DeployParams {
  DriverParams driver;          ///< The driver's.
  MoveBaseServerParams server;  ///< The move_base action's (a task with a goal).
  GoalPursuitParams pursuit;    ///< A goal's pursuit's (a task with a goal).
  LocalPlannerParams local;     ///< What drives towards the goal (a task with a goal).
};

template <typename C, typename V>
IfConfig<C, DeployParams> visitFields(C& c, V&& v) {
  v("checkpoint", c.driver.checkpoint, AnyValue{"", "required"},
    "Checkpoint file, or a run directory (its checkpoints/best.pt).");
  v("task", c.driver.task, AnyValue{"", "empty: the checkpoint's"},
    "The task the policy was trained on; given, it must be the checkpoint's.");
  v("odom_topic", c.driver.odom_topic, AnyValue{}, "nav_msgs/Odometry of the robot.");
  v("cmd_vel_topic", c.driver.cmd_vel_topic, AnyValue{},
    "geometry_msgs/Twist the robot's driver takes.");
  v("command_topic", c.driver.command_topic, AnyValue{},
    "Command task: geometry_msgs/Vector3, the command (x, y) in the odometry frame.");
  v("odom_timeout", c.driver.odom_timeout, positive("s, wall"), "Older odometry stops the robot.");
  v("wheel_radius", c.driver.wheel_radius, atLeast(0.0, "m", "0: the checkpoint's"),
    "Wheel radius for wheel targets -> Twist: the robot driver's, which turns the Twist back into "
    "wheel speeds (stock Jetbot: 0.03015 m). 0: the trained robot's (the checkpoint's "
    "wheel_radius), or robot_description's where the checkpoint has none; given, it overrides "
    "the checkpoint's with a warning naming both.");
  v("wheel_separation", c.driver.wheel_separation, atLeast(0.0, "m", "0: the checkpoint's"),
    "Wheel separation for wheel targets -> Twist: the robot driver's (stock Jetbot: 0.1016 m); "
    "0: as wheel_radius.");
  v("dof_names", c.driver.dof_names, NameList{},
    "The two wheel joints in the policy's action order (used with robot_description).");
  v("scan_topic", c.driver.scan_topic, AnyValue{},
    "Navigation: the robot's sensor_msgs/LaserScan.");
  v("image_topic", c.driver.image_topic, AnyValue{},
    "Image policies: the robot's camera, sensor_msgs/Image (rgb8, bgr8, rgba8, bgra8 or mono8) "
    "through image_transport, resized by area averaging to the size the policy was trained on.");
  v("image_transport", c.driver.image_transport, AnyValue{},
    "Image policies: the image_transport the images come by (raw; compressed, theora where "
    "their plugins are installed): image_topic's base topic is subscribed through it.");
  v("image_timeout", c.driver.image_timeout, positive("s, wall"),
    "Image policies: an older image stops the robot.");
  v("goal_topic", c.server.goal_topic, AnyValue{},
    "Navigation: geometry_msgs/PoseStamped goals (RViz's 2D Nav Goal), transformed into the "
    "odometry frame with tf2.");
  v("outcome_topic", c.server.outcome_topic, AnyValue{},
    "Navigation: std_msgs/String, what became of each goal (accepted, reached, refused: ...).");
  v("scan_timeout", c.driver.scan_timeout, positive("s, wall"),
    "Navigation: an older scan stops the robot.");
  v("action_name", c.server.action_name, AnyValue{},
    "Navigation: the move_base_msgs/MoveBaseAction server's name (actionlib), resolved in the "
    "node's namespace as move_base's is.");
  v("xy_goal_tolerance", c.pursuit.xy_goal_tolerance,
    inRange(0.0, 100.0, "m", "0: the checkpoint's goal_radius"),
    "Navigation: a goal is reached within this of the robot's odometry origin (move_base's local "
    "planners' name; the task's goal test). 0: the radius the policy was trained with; given, it "
    "overrides it with a warning naming both.");
  v("yaw_goal_tolerance", c.pursuit.yaw_goal_tolerance,
    Range<double>{0.0, 7.0, true, false, "rad", ">= pi: any heading"},
    "Navigation: once within xy_goal_tolerance the robot turns in place to the goal's heading "
    "within this; the goal SUCCEEDS then.");
  v("turn_speed", c.pursuit.turn_speed, positiveUpTo(10.0, "rad/s"),
    "Navigation: the top rate of a turn in place (towards the way, to the goal's heading); the "
    "turn slows down proportionally (4 rad/s per rad) within 0.75 rad of its end.");
  v("goal_timeout", c.pursuit.goal_timeout, atLeast(0.0, "s, wall", "0: never"),
    "Navigation: a goal not reached by then is ABORTED (timed out).");
  v("controller_patience", c.pursuit.controller_patience, positive("s, wall"),
    "Navigation: inputs stale this long ABORT the goal (stale inputs); the robot stands while "
    "they are.");
  v("oscillation_timeout", c.pursuit.oscillation_timeout, atLeast(0.0, "s, wall", "0: never"),
    "Navigation: a robot that has not moved oscillation_distance for this long is stuck: it "
    "backs off, plans again and turns to the way (a recovery), and the goal is ABORTED after "
    "max_recoveries.");
  v("oscillation_distance", c.pursuit.oscillation_distance, positiveUpTo(100.0, "m"),
    "Navigation: moving this far from where the robot last made progress is progress.");
  v("max_recoveries", c.pursuit.max_recoveries, inRange(0, 1000),
    "Navigation: recoveries of a stuck robot, or of one whose re-plan finds no way, before its "
    "goal is ABORTED.");
  v("recovery_backoff", c.pursuit.recovery_backoff, positiveUpTo(10.0, "m"),
    "Navigation: a recovery backs off this far (at 0.1 m/s), then plans again.");
  v("max_planning_retries", c.pursuit.max_planning_retries, inRange(0, 1000),
    "Navigation with a map: a recovery's plan that finds no way is tried again this often, once "
    "per path_replan_period with the robot standing, before the next recovery (move_base's "
    "name).");
  v("carrot_distance", c.pursuit.carrot_distance, atLeast(0.0, "m", "0: the goal itself"),
    "Navigation with a map, a policy that observes no path: a path is planned and the policy's "
    "goal is the point this far along it (a carrot), so that goals behind walls are reached.");
  v("map_topic", c.pursuit.map_topic, AnyValue{"", "empty: none"},
    "Navigation: nav_msgs/OccupancyGrid (map_server's /map), looked up in its header's frame "
    "through tf2; a goal off its free cells is refused. A policy that follows a path plans on it "
    "(required then).");
  v("footprint_radius", c.pursuit.footprint_radius, atLeast(0.0, "m", "0: the checkpoint's"),
    "Path: the robot's footprint radius the map is inflated by. 0: the trained robot's (the "
    "checkpoint's footprint_radius); given, it overrides it with a warning naming both.");
  v("path_clearance", c.pursuit.path_clearance, atLeast(-1.0, "m", "< 0: the checkpoint's"),
    "Path: the clearance beyond the footprint a path keeps where there is room. Negative: the "
    "training's (the checkpoint's path_clearance, nav/path_clearance); given, it overrides it "
    "with a warning naming both.");
  v("path_clearance_cost", c.pursuit.path_clearance_cost,
    atLeast(-1.0, "", "< 0: the checkpoint's"),
    "Path: what a cell at the footprint costs beyond its length, per cell length. Negative: the "
    "training's (nav/path_clearance_cost); given, it overrides it with a warning.");
  v("path_replan_distance", c.pursuit.path_replan_distance, positiveUpTo(100.0, "m"),
    "Path: the robot farther than this from the path re-plans from where it is.");
  v("path_blocked_distance", c.pursuit.path_blocked_distance, atLeast(0.0, "m", "0: off"),
    "Path: a scan point the map does not hold within the footprint of the path this far ahead "
    "re-plans around what the scan sees.");
  v("path_replan_period", c.pursuit.path_replan_period, positive("s, wall"),
    "Path: at most one re-plan per this.");
  v("local_planner", c.local.planner, AnyValue{},
    "Navigation: what drives towards a goal where the policy would: policy (the checkpoint's), "
    "or dwa, the dynamic window approach as move_base's dwa_local_planner defines it (the "
    "navigation benchmark's classical rows) on the scan and the way to the goal (the plan, or "
    "the straight line without a map), with the dwa/... parameters below (dwa/max_vel_x: the "
    "policy's top speed unless given). The goal's turns, arrival and recoveries are the same.");
  visitFields(c.local.dwa, v);
}

/// checkpoint given; dof_names two wheel joints.
void checkFieldRules(const DeployParams& params);

/// The settings of `params` that training knew and that are left unset (wheel geometry,
/// footprint, goal tolerance, path clearance and cost) take the checkpoint's observation contract
/// `trained`; one given anyway is kept, and for each that differs from the checkpoint's a line
/// "PARAM = GIVEN overrides the checkpoint's FIELD = VALUE" is returned (the node warns of it).
std::vector<std::string> takeTrainedSettings(DeployParams& params, const ObserverSpec& trained);

}  // namespace jetbot_rl
