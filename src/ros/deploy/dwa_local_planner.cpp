#include "jetbot_rl/ros/deploy/dwa_local_planner.h"

#include <algorithm>
#include <cmath>

namespace jetbot_rl {

DwaLocalPlanner::DwaLocalPlanner(const DwaConfig& config, double footprint_radius)
    : planner_(config, footprint_radius) {}

PlanarTwist DwaLocalPlanner::step(const MeasuredState& state, const sensor_msgs::LaserScan& scan,
                                  const std::vector<Eigen::Vector2d>& path,
                                  const Eigen::Vector2d& local_goal) {
  const RootState& s = state.root;
  setRobot(in_, s.position, s.orientation, s.com_linear_velocity, s.angular_velocity);
  if (path.empty()) {
    // No plan: the straight line, its local goal local_goal_distance along it (or the goal).
    in_.path = {in_.position, state.goal};
    const Eigen::Vector2d way = state.goal - in_.position;
    const double reach = planner_.config().local_goal_distance;
    in_.local_goal =
        way.norm() > reach ? Eigen::Vector2d(in_.position + reach * way.normalized()) : state.goal;
  } else {
    in_.path = path;
    in_.local_goal = local_goal;
  }
  // The returns in the odometry frame, as the simulated scan gives them to the benchmark's DWA
  // (REP 117: +inf and NaN are none, -inf or below range_min is something at range_min).
  in_.obstacles.clear();
  const Eigen::Vector2d heading(std::cos(in_.yaw), std::sin(in_.yaw));
  const Eigen::Vector2d left(-heading.y(), heading.x());
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    double r = scan.ranges[k];
    if (std::isnan(r) || r > scan.range_max) continue;
    r = std::max(r, static_cast<double>(scan.range_min));
    const double angle = scan.angle_min + static_cast<double>(k) * scan.angle_increment;
    in_.obstacles.push_back(in_.position + r * std::cos(angle) * heading +
                            r * std::sin(angle) * left);
  }
  const DwaCommand command = planner_.plan(in_);
  if (!command.found) ++blocked_;
  return {command.speed, command.yaw_rate};
}

}  // namespace jetbot_rl
