#include "jetbot_rl/ppo/iteration_stats.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace jetbot_rl {
namespace ppo {
namespace {

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

std::string duration(double s) {
  char buf[32];
  if (!std::isfinite(s)) return "?";
  if (s < 60.0) {
    std::snprintf(buf, sizeof(buf), "%.1f s", s);
  } else {
    const long total = std::lround(s);
    std::snprintf(buf, sizeof(buf), "%ld:%02ld min", total / 60, total % 60);
  }
  return buf;
}

}  // namespace

std::vector<std::string> statsColumns(const std::vector<std::string>& obs_names) {
  std::vector<std::string> columns{"iteration",           "env_steps",       "mean_reward_per_step",
                                   "mean_episode_return", "env_steps_per_s", "elapsed_s",
                                   "collection_s",        "update_s",        "value_loss",
                                   "surrogate_loss",      "entropy",         "approx_kl",
                                   "learning_rate",       "action_std",      "episodes",
                                   "success_rate",        "collision_rate",  "timeout_rate",
                                   "obs_samples"};
  for (const std::string& name : obs_names) columns.push_back("obs_mean_" + name);
  return columns;
}

std::vector<double> statsValues(const IterationStats& s) {
  std::vector<double> values{static_cast<double>(s.iteration),
                             static_cast<double>(s.env_steps),
                             s.mean_reward_per_step,
                             s.mean_episode_return,
                             s.env_steps_per_s,
                             s.elapsed_s,
                             s.collection_s,
                             s.update_s,
                             s.update.value_loss,
                             s.update.surrogate_loss,
                             s.update.entropy,
                             s.update.approx_kl,
                             s.update.learning_rate,
                             s.action_std,
                             static_cast<double>(s.episodes),
                             s.success_rate,
                             s.collision_rate,
                             s.timeout_rate,
                             static_cast<double>(s.obs_samples)};
  values.insert(values.end(), s.obs_means.begin(), s.obs_means.end());
  return values;
}

std::string csvHeader(const std::vector<std::string>& obs_names) {
  std::string h;
  for (const std::string& c : statsColumns(obs_names)) h += (h.empty() ? "" : ",") + c;
  return h;
}

std::string csvRow(const IterationStats& s) {
  std::string row;
  bool first = true;
  for (double v : statsValues(s)) {
    row += (first ? "" : ",") + number(v);
    first = false;
  }
  return row;
}

std::string progressLine(const IterationStats& s) {
  char outcomes[96] = "";
  if (s.success_rate > 0.0 || s.collision_rate > 0.0) {  // a task with goals
    std::snprintf(outcomes, sizeof(outcomes), " | success %.2f collision %.2f", s.success_rate,
                  s.collision_rate);
  }
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "iteration %lld/%lld | env steps %lld | reward/step %.4f | episode return %s%s | "
                "%.0f env steps/s | elapsed %s | left %s",
                static_cast<long long>(s.iteration), static_cast<long long>(s.iterations),
                static_cast<long long>(s.env_steps), s.mean_reward_per_step,
                std::isnan(s.mean_episode_return)
                    ? "-"
                    : number(std::round(s.mean_episode_return * 100) / 100).c_str(),
                outcomes, s.env_steps_per_s, duration(s.elapsed_s).c_str(),
                duration(s.time_left_s).c_str());
  return buf;
}

}  // namespace ppo
}  // namespace jetbot_rl
