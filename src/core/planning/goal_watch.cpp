#include "jetbot_rl/planning/goal_watch.h"

#include <sstream>

namespace jetbot_rl {

void GoalWatch::start(double now, const Eigen::Vector2d& p) {
  started_ = now;
  restartProgress(now, p);
}

void GoalWatch::restartProgress(double now, const Eigen::Vector2d& p) {
  progress_time_ = now;
  progress_point_ = p;
}

GoalWatch::Verdict GoalWatch::check(double now, const Eigen::Vector2d& p, std::string& why) {
  if (config_.timeout > 0.0 && now - started_ > config_.timeout) {
    std::ostringstream s;
    s << "timed out: not reached within " << config_.timeout << " s (goal_timeout)";
    why = s.str();
    return Verdict::kTimedOut;
  }
  if ((p - progress_point_).norm() >= config_.oscillation_distance) {
    restartProgress(now, p);
  } else if (config_.oscillation_timeout > 0.0 &&
             now - progress_time_ > config_.oscillation_timeout) {
    std::ostringstream s;
    s << "stuck: moved less than " << config_.oscillation_distance << " m in "
      << config_.oscillation_timeout << " s (oscillation_distance, oscillation_timeout)";
    why = s.str();
    return Verdict::kStuck;
  }
  return Verdict::kPursuing;
}

}  // namespace jetbot_rl
