#pragma once

// The navigation field's metrics of a policy's episodes (issue 48): success weighted by path
// length (SPL, Anderson et al. 2018), the BARN challenge's score, time over the optimal time, path
// over the shortest path and smoothness; counted by jetbot_rl_evaluate and the benchmark.

#include <Eigen/Core>
#include <vector>

#include "jetbot_rl/eval/episode_loop.h"

namespace jetbot_rl {

class NavigationTask;

/// The metrics of the episodes counted (successes, or all episodes where it says so).
struct NavigationMetricsResult {
  double time_to_goal = 0.0;  ///< Mean over the successes [s].
  /// Mean over the successes of the distance driven to the goal's circle over the shortest path's
  /// length to it (planned for the footprint without the clearance cost).
  double path_ratio = 0.0;
  /// Mean over every episode of success x shortest / max(driven, shortest) (SPL).
  double spl = 0.0;
  /// Mean over every episode of BARN's score: success x optimal time / clip(time, 4 optimal time,
  /// 8 optimal time), the optimal time the shortest path at top speed; in [0, 0.25]. NaN without
  /// a top speed.
  double barn_score = 0.0;
  /// Mean over the successes of the time to the goal over the optimal time. NaN without a top
  /// speed.
  double time_ratio = 0.0;
  /// Mean over the successes' steps of |change of the yaw rate| / control step [rad/s^2].
  double angular_smoothness = 0.0;
  /// Mean over the successes' steps of |change of the forward speed| / control step [m/s^2].
  double linear_smoothness = 0.0;
};

/**
 * Watches a navigation batch through runEpisodes(): each episode's shortest path (planPath on
 * the layout, from its start to its goal's circle), the distance its root drove (control step by
 * control step; the last step, whose end the reset hides, as far as the goal's circle), its time,
 * and its body speeds from step to step. `top_speed` [m/s] (topSpeed()) sets the optimal time.
 */
class NavigationMetrics : public EpisodeObserver {
 public:
  NavigationMetrics(const BatchedEnv& env, const NavigationTask& task, double top_speed);

  void beforeStep(const BatchedEnv& env) override;
  void episodeEnded(int env, std::uint8_t outcome, std::uint32_t steps) override;
  void afterStep(const BatchedEnv& env, const StepResult& result) override;

  /// What the episodes counted so far give.
  NavigationMetricsResult result() const;

 private:
  const NavigationTask& task_;
  const double radius_, control_dt_, top_speed_;
  std::vector<double> driven_, shortest_;
  std::vector<Eigen::Vector2d> before_, goal_;
  std::vector<double> yaw_rate_, speed_;          // before the step
  std::vector<double> angular_sum_, linear_sum_;  // this episode's |changes|
  std::vector<int> changes_;                      // this episode's steps with a change
  int episodes_ = 0, successes_ = 0, ratios_ = 0, smooth_steps_ = 0;
  double time_sum_ = 0.0, ratio_sum_ = 0.0, spl_sum_ = 0.0, barn_sum_ = 0.0, optimal_sum_ = 0.0;
  int optimal_ = 0;
  double angular_total_ = 0.0, linear_total_ = 0.0;
};

}  // namespace jetbot_rl
