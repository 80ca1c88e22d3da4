#pragma once

// How a training run is driven and where it writes: the trainer's run parameters, without the
// learner (no libtorch here: the parameter readers and the docs include it).

#include <cstdint>
#include <string>

#include "jetbot_rl/config/config_fields.h"

namespace jetbot_rl {
namespace ppo {

/// What makes an iteration the best so far (checkpoints/best.pt).
enum class BestBy { kRewardPerStep, kEpisodeReturn, kLast };

/// How a training run is driven and where it writes.
struct RunnerOptions {
  std::int64_t iterations = 100;  ///< The run ends after this many iterations (resume included).
  std::string run_dir;            ///< Run directory (created): CSV, config, checkpoints.
  std::string resume;             ///< Checkpoint to continue from; empty: a new run.
  int save_interval = 10;         ///< Save checkpoints/latest.pt every this many iterations.
  double target_reward = 0.54;    ///< Reported: first iteration with mean reward/step >= this.
  BestBy best_by = BestBy::kRewardPerStep;  ///< What makes checkpoints/best.pt.
  std::string extra_config;  ///< YAML appended to config.yaml (trainer params, env spec).
  /// obs_mean_* columns: mean of each observation component over the rollout's samples taken at
  /// this step of their episode or later (0: the reset's observation) [control steps]; -1: the
  /// second half of an episode, max_episode_length / 2.
  int obs_stats_from_step = -1;
};

/// The parameters among RunnerOptions (extra_config is not one), with their rules.
template <typename C, typename V>
IfConfig<C, RunnerOptions> visitFields(C& c, V&& v) {
  v("iterations", c.iterations, atLeast<std::int64_t>(1),
    "The run ends after this many iterations (a resumed run's included).");
  v("run_dir", c.run_dir, AnyValue{"", "empty: ~/.ros/jetbot_rl/TIME_seedSEED"},
    "Run directory (created): progress.csv, config.yaml, checkpoints, exported policy.");
  v("resume", c.resume, AnyValue{"", "empty: a new run"},
    "Checkpoint file or run directory (its checkpoints/latest.pt) to continue from.");
  v("save_interval", c.save_interval, atLeast(1),
    "Write checkpoints/latest.pt every this many iterations (and at the end).");
  v("target_reward", c.target_reward,
    Range<double>{-1e300, 1e300, false, false, "m/s", "reported only"},
    "Reported: the first iteration whose mean reward per step reaches this.");
  v("best_by", c.best_by, AnyValue{},
    "Which iteration's policy is checkpoints/best.pt (and exported/policy.pt): reward_per_step, "
    "the highest mean reward per step of an iteration; episode_return, the highest mean return "
    "of the last 100 episodes (steadier where the reward per step swings with the episodes' "
    "phase, as with rounds of robots: docs/team.md); last, the last iteration (with a "
    "curriculum, whose later iterations are harder, rewards of different iterations do not "
    "compare).");
  v("obs_stats_from_step", c.obs_stats_from_step,
    atLeast(-1, "control steps", "-1: max_episode_length / 2"),
    "progress.csv's obs_mean_<name> columns: mean of each observation over the rollout's "
    "samples at this step of their episode or later.");
}

inline const EnumNameList<BestBy>& enumNames(BestBy) {
  static const EnumNameList<BestBy> names{{BestBy::kRewardPerStep, "reward_per_step"},
                                          {BestBy::kEpisodeReturn, "episode_return"},
                                          {BestBy::kLast, "last"}};
  return names;
}

}  // namespace ppo
}  // namespace jetbot_rl
