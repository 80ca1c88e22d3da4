#pragma once

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <nav_msgs/Odometry.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <ros/wall_timer.h>
#include <sensor_msgs/LaserScan.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/planning/speed_limit.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/common/drop_counter.h"
#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/ros/deploy/dwa_local_planner.h"
#include "jetbot_rl/ros/deploy/fresh_input.h"
#include "jetbot_rl/ros/deploy/goal_pursuit.h"
#include "jetbot_rl/ros/deploy/image_input.h"
#include "jetbot_rl/ros/deploy/scan_beams.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/// How a checkpoint's policy runs: at 1 / its control step, with its action bounds, its actions
/// wheel targets or a twist (v, omega).
struct PolicyRun {
  double control_rate = 0.0;  ///< [Hz]
  bool twist = false;         ///< Actions (linear_x, angular_z) rather than wheel targets.
  std::vector<double> action_high;
  std::string checkpoint;  ///< Its file, for messages.
  /// A policy that follows a global path: the observed point's distance along it [m]; else 0.
  double path_lookahead = 0.0;
};

/// The PolicyRun of `policy`'s checkpoint; ConfigError naming the file for a checkpoint without
/// its env's spec (format 1).
PolicyRun policyRunOf(const ppo::Policy& policy, const std::string& checkpoint);

/// The observer of the policy trained on `trained` (a checkpoint's env spec: its observation
/// contract) with its goal test within `goal_radius` [m]: makeObserver(), the same code the
/// simulated task observes with. ConfigError when its observation's names are not the ones the
/// policy of `checkpoint` was trained on.
std::unique_ptr<TaskObserver> observerOf(const BatchSpec& trained, double goal_radius,
                                         const std::string& checkpoint);

/**
 * The deploy node's driver, one for every task: the robot's inputs the task's observer needs
 * (odometry always; a scan resampled to the policy's beams and goals for navigation; a command
 * for the command task; camera images at the policy's size for an image policy), each with its
 * freshness, become the observation through the same
 * TaskObserver the simulated task observes with; the policy's mean action goes out as a Twist at
 * the policy's control rate (with `local_planner: dwa` the DWA's twist on the same inputs and goals
 * instead). The robot stands while an input is stale (zero Twists; with goals
 * one zero, and the goal pursued on); a task with goals is pursued by GoalPursuit (the move_base
 * action, plans, the goal's heading, recovery) and is quiet without one: one zero Twist when it
 * stops, none while idle. The policy's memory starts over with each goal or command and after
 * each stop for stale input. A 1 Hz DiagnosticStatus
 * "<node>: deploy" tells the inputs' ages and why the robot stands.
 */
class DeployDriver {
 public:
  /// `p`: with the checkpoint's settings taken (takeTrainedSettings()); the scan is read at the
  /// beams of the policy's contract (a task that observes a scan); `kinematics`: wheel targets
  /// -> Twist for a policy with wheel actions.
  DeployDriver(ros::NodeHandle& nh, ros::NodeHandle& pnh, ppo::Policy& policy,
               const TaskObserver& observer, const DeployParams& p, const PolicyRun& run,
               const std::optional<DiffDrive>& kinematics);
  /// Stops ticking and leaves the robot standing: a zero Twist, written out before returning.
  void stop();

 private:
  void onTick(const ros::WallTimerEvent&);
  void onStatus(const ros::WallTimerEvent&);
  void onCommand(const geometry_msgs::Vector3::ConstPtr& msg);
  /// The twist of one policy step on the current inputs (which are fresh).
  geometry_msgs::Twist act(const MeasuredState& state);
  /// The fastest forward v [m/s] the checkpoint's speed limit allows on the latest scan
  /// (`v_max` without a limit).
  double speedCap(double v_max);
  /// The twist of one DWA step (local_planner dwa) on the same inputs, along the goal's way.
  geometry_msgs::Twist dwaStep(const MeasuredState& state);
  /// Stops with a zero last action; `fresh_start`: the memory starts over too.
  void stand(const std::string& why, bool fresh_start);
  /// Publishes `twist`; with goals, a stop only once (quiet while idle).
  void publish(const geometry_msgs::Twist& twist, bool stop);

  ppo::Policy& policy_;
  const TaskObserver& observer_;
  PolicyRun run_;
  const ObserverSpec& trained_;  // the policy's observation contract (its checkpoint's)
  std::optional<DiffDrive> kinematics_;
  DropCounter drops_;
  FreshInput<nav_msgs::Odometry> odom_;
  std::unique_ptr<FreshInput<sensor_msgs::LaserScan>> scan_;  // a task that observes a scan
  std::unique_ptr<ImageInput> image_;                         // a policy that observes images
  std::unique_ptr<GoalPursuit> pursuit_;                      // a task with goals
  std::unique_ptr<DwaLocalPlanner> dwa_;     // local_planner dwa: it drives instead of the policy
  std::unique_ptr<SpeedLimit> speed_limit_;  // the checkpoint's, for the latest scan's geometry
  double clear_ahead_ = 0.0;                 // [m], what it last saw, for diagnostics
  std::vector<Eigen::Vector2d> way_;         // the DWA's path, reused
  bool stopped_ = false;                     // the last Twist published was a stop
  ros::Subscriber command_sub_;              // a task with a command
  ros::Publisher cmd_vel_pub_, status_pub_;
  ros::WallTimer timer_, status_timer_;
  Eigen::Vector2d command_ = Eigen::Vector2d::UnitX();
  std::vector<float> ranges_, obs_, actions_, last_action_;
  std::string standing_;  // why the robot stands ("" while it drives), for diagnostics
};

}  // namespace jetbot_rl
