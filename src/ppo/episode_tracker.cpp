#include "jetbot_rl/ppo/episode_tracker.h"

#include <limits>
#include <numeric>

#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {
namespace ppo {

EpisodeTracker::EpisodeTracker(int num_envs, std::size_t window)
    : current_(static_cast<std::size_t>(num_envs), 0.0),
      skip_(static_cast<std::size_t>(num_envs), 0),
      window_(window) {}

const std::vector<double>& EpisodeTracker::add(const StepResult& batch) {
  for (std::size_t i = 0; i < current_.size() && i < batch.rewards.size(); ++i) {
    current_[i] += batch.rewards[i];
  }
  ended_.clear();
  for (std::size_t i = 0; i < batch.reset_env_ids.size(); ++i) {
    const std::uint32_t id = batch.reset_env_ids[i];
    if (id >= current_.size()) continue;
    // A round's wait (rounds) is no episode: its zero rewards are dropped.
    const bool waited = i < batch.outcomes.size() && outcomeRate(batch.outcomes[i]) < 0;
    if (skip_[id] || waited) {
      skip_[id] = 0;
      current_[id] = 0.0;
      continue;
    }
    ended_.push_back(current_[id]);
    recent_.push_back(current_[id]);
    if (recent_.size() > window_) recent_.pop_front();
    current_[id] = 0.0;
    ++episodes_;
  }
  return ended_;
}

void EpisodeTracker::skipCurrent(std::uint32_t id) {
  if (id < skip_.size()) skip_[id] = 1;
}

double EpisodeTracker::meanReturn() const {
  if (recent_.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::accumulate(recent_.begin(), recent_.end(), 0.0) / recent_.size();
}

}  // namespace ppo
}  // namespace jetbot_rl
