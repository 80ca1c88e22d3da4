#include "jetbot_rl/eval/navigation_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace {

/// The shortest path's length from env `e`'s start to its goal [m]; NaN when there is none.
double shortestPath(const BatchedEnv& env, const NavigationTask& task, int e) {
  const EnvLayout& layout = env.view(e).layout();
  const WorldModel& world = *env.world();
  const FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles);
  std::vector<Eigen::Vector2d> path;
  if (!planPath(grid, layout.start, task.goal(e), 0.0, path)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

double yawRate(const RootState& s) { return s.angular_velocity.z(); }
double forwardSpeed(const RootState& s) { return s.comLinearVelocityBody().x(); }

}  // namespace

NavigationMetrics::NavigationMetrics(const BatchedEnv& env, const NavigationTask& task,
                                     double top_speed)
    : task_(task),
      radius_(task.config().goal_radius),
      control_dt_(env.controlDt()),
      top_speed_(top_speed),
      driven_(env.numEnvs(), 0.0),
      shortest_(env.numEnvs()),
      before_(env.numEnvs()),
      goal_(env.numEnvs()),
      yaw_rate_(env.numEnvs(), 0.0),
      speed_(env.numEnvs(), 0.0),
      angular_sum_(env.numEnvs(), 0.0),
      linear_sum_(env.numEnvs(), 0.0),
      changes_(env.numEnvs(), 0) {
  for (int e = 0; e < env.numEnvs(); ++e) shortest_[e] = shortestPath(env, task_, e);
}

void NavigationMetrics::beforeStep(const BatchedEnv& env) {
  for (int e = 0; e < env.numEnvs(); ++e) {
    const RootState s = env.view(e).rootState();
    before_[e] = s.position.head<2>();
    yaw_rate_[e] = yawRate(s);
    speed_[e] = forwardSpeed(s);
    goal_[e] = task_.goal(e);
  }
}

void NavigationMetrics::episodeEnded(int e, std::uint8_t outcome, std::uint32_t steps) {
  ++episodes_;
  const bool success = outcome == static_cast<std::uint8_t>(Outcome::kSuccess);
  // Shortest and driven both end at the goal's circle; the last step (whose end the reset hid)
  // counts as far as the circle.
  const double shortest = shortest_[e] - radius_;
  const double driven = driven_[e] + std::max(0.0, (goal_[e] - before_[e]).norm() - radius_);
  const bool known = shortest > 0.0;  // NaN (no path) or a start inside the circle: not counted
  const double time = steps * control_dt_;
  if (known && success) spl_sum_ += shortest / std::max(driven, shortest);
  if (known && top_speed_ > 0.0) {
    const double optimal = shortest / top_speed_;
    if (success) {
      barn_sum_ += optimal / std::clamp(time, 4.0 * optimal, 8.0 * optimal);
      optimal_sum_ += time / optimal;
      ++optimal_;
    }
  }
  if (!success) return;
  ++successes_;
  time_sum_ += time;
  if (known) {
    ratio_sum_ += driven / shortest;
    ++ratios_;
  }
  angular_total_ += angular_sum_[e];
  linear_total_ += linear_sum_[e];
  smooth_steps_ += changes_[e];
}

void NavigationMetrics::afterStep(const BatchedEnv& env, const StepResult& r) {
  std::vector<std::uint8_t> reset(env.numEnvs(), 0);
  for (std::uint32_t e : r.reset_env_ids) reset[e] = 1;
  for (int e = 0; e < env.numEnvs(); ++e) {
    if (reset[e]) {  // a new episode: its own path, distance and speeds
      driven_[e] = 0.0;
      shortest_[e] = shortestPath(env, task_, e);
      angular_sum_[e] = linear_sum_[e] = 0.0;
      changes_[e] = 0;
      continue;
    }
    const RootState s = env.view(e).rootState();
    driven_[e] += (s.position.head<2>() - before_[e]).norm();
    angular_sum_[e] += std::abs(yawRate(s) - yaw_rate_[e]) / control_dt_;
    linear_sum_[e] += std::abs(forwardSpeed(s) - speed_[e]) / control_dt_;
    ++changes_[e];
  }
}

NavigationMetricsResult NavigationMetrics::result() const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  NavigationMetricsResult m;
  m.time_to_goal = successes_ > 0 ? time_sum_ / successes_ : 0.0;
  m.path_ratio = ratios_ > 0 ? ratio_sum_ / ratios_ : 0.0;
  m.spl = episodes_ > 0 ? spl_sum_ / episodes_ : 0.0;
  m.barn_score = top_speed_ > 0.0 ? (episodes_ > 0 ? barn_sum_ / episodes_ : 0.0) : nan;
  m.time_ratio = top_speed_ > 0.0 ? (optimal_ > 0 ? optimal_sum_ / optimal_ : 0.0) : nan;
  m.angular_smoothness = smooth_steps_ > 0 ? angular_total_ / smooth_steps_ : 0.0;
  m.linear_smoothness = smooth_steps_ > 0 ? linear_total_ / smooth_steps_ : 0.0;
  return m;
}

}  // namespace jetbot_rl
