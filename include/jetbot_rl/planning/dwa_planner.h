#pragma once

// The dynamic window approach as move_base's dwa_local_planner defines it (Fox, Burgard and Thrun
// 1997; its parameters' names and meanings): the classical local planner the navigation benchmark
// sets beside the learnt one (issue 48). Debian has no move_base: this one is ours.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {

/// dwa_local_planner's parameters (`dwa/...`), with costmap_2d's inflation for the obstacle
/// cost; defaults for the Jetbot (0.6 m/s) where dwa_local_planner's are for a PR2.
struct DwaConfig {
  double max_vel_x = 0.6;                 ///< [m/s]
  double min_vel_x = 0.0;                 ///< [m/s] (0: never backwards)
  double max_vel_theta = 2.0;             ///< [rad/s]
  double acc_lim_x = 2.5;                 ///< [m/s^2]
  double acc_lim_theta = 3.2;             ///< [rad/s^2]
  double sim_time = 1.7;                  ///< Trajectories forward-simulated this long [s].
  double sim_granularity = 0.025;         ///< Step between a trajectory's points [m].
  double sim_period = 0.05;               ///< The controller's period: the window's reach [s].
  int vx_samples = 3;                     ///< Forward speeds sampled in the window.
  int vth_samples = 20;                   ///< Yaw rates sampled in the window.
  double path_distance_bias = 32.0;       ///< Weight of staying near the global path.
  double goal_distance_bias = 24.0;       ///< Weight of getting near the local goal.
  double occdist_scale = 0.01;            ///< Weight of the obstacle cost (0 to 252).
  double forward_point_distance = 0.325;  ///< The alignment point ahead of the robot [m].
  double inflation_radius = 0.55;     ///< costmap_2d: cells within this of an obstacle cost [m].
  double cost_scaling_factor = 10.0;  ///< costmap_2d: how fast the cost falls off [1/m].
  double local_goal_distance = 2.0;   ///< The local goal: this far along the path [m].
  double footprint_padding = 0.0;     ///< costmap_2d: added to the footprint's radius [m].
};

template <typename C, typename V>
IfConfig<C, DwaConfig> visitFields(C& c, V&& v) {
  const Range<double> speed{0.0, 100.0, false, false, "m/s"};
  v("dwa/max_vel_x", c.max_vel_x, Range<double>{0.0, 100.0, true, false, "m/s"},
    "The highest forward speed it commands.");
  v("dwa/min_vel_x", c.min_vel_x, speed, "The lowest forward speed it commands (0: never back).");
  v("dwa/max_vel_theta", c.max_vel_theta, Range<double>{0.0, 100.0, true, false, "rad/s"},
    "The highest yaw rate it commands, either way.");
  v("dwa/acc_lim_x", c.acc_lim_x, Range<double>{0.0, 1000.0, true, false, "m/s^2"},
    "Forward acceleration limit: the dynamic window's reach in sim_period.");
  v("dwa/acc_lim_theta", c.acc_lim_theta, Range<double>{0.0, 1000.0, true, false, "rad/s^2"},
    "Yaw acceleration limit.");
  v("dwa/sim_time", c.sim_time, Range<double>{0.0, 100.0, true, false, "s"},
    "How long each sampled velocity is forward-simulated.");
  v("dwa/sim_granularity", c.sim_granularity, Range<double>{0.0, 10.0, true, false, "m"},
    "The step between a trajectory's points checked for obstacles.");
  v("dwa/sim_period", c.sim_period, Range<double>{0.0, 10.0, true, false, "s"},
    "The controller's period (1 / controller_frequency): velocities reachable within it are "
    "sampled.");
  v("dwa/vx_samples", c.vx_samples, inRange(1, 1000), "Forward speeds sampled.");
  v("dwa/vth_samples", c.vth_samples, inRange(1, 1000), "Yaw rates sampled.");
  v("dwa/path_distance_bias", c.path_distance_bias, atLeast(0.0),
    "Weight of a trajectory's distance from the global path.");
  v("dwa/goal_distance_bias", c.goal_distance_bias, atLeast(0.0),
    "Weight of a trajectory's distance from the local goal.");
  v("dwa/occdist_scale", c.occdist_scale, atLeast(0.0),
    "Weight of the highest obstacle cost (0-252) along a trajectory.");
  v("dwa/forward_point_distance", c.forward_point_distance, atLeast(0.0, "m"),
    "The point this far ahead of a trajectory's end is scored as well (its alignment).");
  v("dwa/inflation_radius", c.inflation_radius, atLeast(0.0, "m"),
    "costmap_2d's inflation: a point within this of an obstacle costs (beyond the footprint).");
  v("dwa/cost_scaling_factor", c.cost_scaling_factor, atLeast(0.0, "1/m"),
    "costmap_2d's fall-off: 252 exp(-factor (distance - footprint radius)).");
  v("dwa/local_goal_distance", c.local_goal_distance, Range<double>{0.0, 1000.0, true, false, "m"},
    "The local goal: the global path's point this far along it past the robot (the local "
    "costmap's edge in move_base).");
  v("dwa/footprint_padding", c.footprint_padding, inRange(0.0, 10.0, "m"),
    "costmap_2d's footprint_padding: added to the robot's footprint radius, within which of a "
    "scan return a trajectory is refused (on a robot whose scanner's range_min exceeds the "
    "footprint, nearer than range_min it sees nothing: pad by the difference).");
}

/// What the planner sees at a control step, in one frame (the env's, or the map's).
struct DwaInput {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< [m]
  double yaw = 0.0;                                    ///< [rad]
  double speed = 0.0;                                  ///< Forward [m/s].
  double yaw_rate = 0.0;                               ///< [rad/s]
  std::vector<Eigen::Vector2d> obstacles;              ///< Scan returns [m].
  std::vector<Eigen::Vector2d> path;                   ///< The global path to the goal [m].
  /// The local goal: local_goal_distance along the path past the robot (a PathTracker's
  /// lookahead()) [m].
  Eigen::Vector2d local_goal = Eigen::Vector2d::Zero();
};

/// The twist it commands.
/// `in`'s robot: its position and heading in the plane from its pose, its forward speed and yaw
/// rate from its velocities (a RootState's fields: both in the pose's frame) [m/s], [rad/s].
void setRobot(DwaInput& in, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
              const Eigen::Vector3d& linear_velocity, const Eigen::Vector3d& angular_velocity);

struct DwaCommand {
  double speed = 0.0, yaw_rate = 0.0;  ///< [m/s], [rad/s]
  bool found = false;  ///< A trajectory clear of obstacles was found (else: turning in place).
};

/**
 * Samples vx_samples x vth_samples velocities in the window the acceleration limits reach from
 * the current ones in sim_period, simulates each for sim_time, and picks the one of least cost,
 * as base_local_planner's SimpleTrajectoryGenerator and scoring do: 0.5 path_distance_bias
 * (distance of the end and of the point forward_point_distance ahead of it from the path) + 0.5
 * goal_distance_bias (their distances from the local goal) + occdist_scale (the highest obstacle
 * cost on the way); a trajectory whose point comes within `robot_radius` [m] of an obstacle is
 * refused. None clear: a turn in place towards the path (move_base's rotate recovery).
 */
class DwaPlanner {
 public:
  /// `config` valid (checkFieldRules); `robot_radius`: the footprint [m].
  DwaPlanner(const DwaConfig& config, double robot_radius);
  DwaCommand plan(const DwaInput& in) const;
  const DwaConfig& config() const { return config_; }

 private:
  /// costmap_2d's cost at `distance` [m] from the nearest obstacle: 253 inside the footprint.
  double obstacleCost(double distance) const;

  DwaConfig config_;
  double robot_radius_;
};

/// min_vel_x <= max_vel_x: ConfigError naming the field otherwise.
void checkFieldRules(const DwaConfig& c);

}  // namespace jetbot_rl
