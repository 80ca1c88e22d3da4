#pragma once

#include <algorithm>
#include <vector>

#include "jetbot_rl/rng.h"
#include "jetbot_rl/world/world_config.h"

namespace jetbot_rl {

/**
 * The difficulty of each env's generated layouts (world/difficulty, world/curriculum), or of its
 * tracks (road/curriculum): every env starts at world/difficulty (a track at 0); with the
 * curriculum, after each run of curriculum_episodes of its episodes it moves up by curriculum_step
 * (to at most 1) when at least curriculum_success of them reached the goal. With curriculum_mix,
 * that share of an env's resets draws its layout at a difficulty uniform in [0, the env's] instead,
 * so that what was learnt on easy layouts is kept. Per env and from its own outcomes and stream
 * only: the same on any thread count.
 */
class Curriculum {
 public:
  Curriculum() = default;
  /// The world's (world/difficulty, world/curriculum...).
  Curriculum(const WorldConfig& config, int num_envs)
      : Curriculum(config.curriculum, config.difficulty, config.curriculum_episodes,
                   config.curriculum_success, config.curriculum_step, config.curriculum_mix,
                   num_envs) {}
  /// Every env at `start`; `enabled`: raised by `step` after each run of `episodes` of its
  /// episodes of which at least `success` (a share) succeeded; `mix` as curriculum_mix.
  Curriculum(bool enabled, double start, int episodes, double success, double step, double mix,
             int num_envs)
      : enabled_(enabled),
        episodes_per_run_(episodes),
        success_(success),
        step_(step),
        mix_(mix),
        difficulty_(num_envs, start),
        episodes_(num_envs, 0),
        successes_(num_envs, 0) {}

  /// Env `env`'s difficulty, in [0, 1].
  double difficulty(int env) const { return difficulty_[env]; }
  /// The difficulty env `env`'s next layout is drawn at: difficulty(env), or with curriculum_mix
  /// one uniform below it (from `rng`, the env's stream; nothing drawn without the mix).
  double drawDifficulty(int env, Rng& rng) const {
    if (!enabled_ || mix_ <= 0.0 || rng.uniform() >= mix_) return difficulty_[env];
    return difficulty_[env] * rng.uniform();
  }
  /// Counts env `env`'s ended episode; raises its difficulty when its run is complete and good.
  void episodeEnded(int env, bool success) {
    if (!enabled_) return;
    successes_[env] += success ? 1 : 0;
    if (++episodes_[env] < episodes_per_run_) return;
    if (successes_[env] >= success_ * episodes_per_run_) {
      difficulty_[env] = std::min(1.0, difficulty_[env] + step_);
    }
    episodes_[env] = 0;
    successes_[env] = 0;
  }

 private:
  bool enabled_ = false;
  int episodes_per_run_ = 1;
  double success_ = 1.0, step_ = 0.0, mix_ = 0.0;
  std::vector<double> difficulty_;
  std::vector<int> episodes_, successes_;
};

}  // namespace jetbot_rl
