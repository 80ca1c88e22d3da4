#pragma once

#include <cstdint>

#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/ppo/policy.h"

namespace jetbot_rl {

/// What a program that plays a policy counts besides the outcomes: it sees every step and every
/// episode that counts (the navigation benchmark's paths, the evaluator's observations).
class EpisodeObserver {
 public:
  virtual ~EpisodeObserver() = default;
  /// Before a step, on the state the policy acts on.
  virtual void beforeStep(const BatchedEnv& /*env*/) {}
  /// Env `env`'s episode that counts (within its quota, not a round's wait) ended with
  /// `outcome`, `steps` control steps long; called before afterStep() of the same step.
  virtual void episodeEnded(int /*env*/, std::uint8_t /*outcome*/, std::uint32_t /*steps*/) {}
  /// After a step, with its result (the ended envs already reset).
  virtual void afterStep(const BatchedEnv& /*env*/, const StepResult& /*result*/) {}
};

/// What an episode loop counted.
struct EpisodeTotals {
  int steps = 0;                         ///< Control steps run.
  double reward_sum = 0.0;               ///< Over every env and step.
  std::int64_t episodes = 0;             ///< Episodes counted.
  std::int64_t outcomes[3] = {0, 0, 0};  ///< Per outcomeRate(): time-out, success, collision.
  std::int64_t mover_collisions = 0;     ///< Of the collisions: with a mover.
  std::int64_t robot_collisions = 0;     ///< Of the collisions: with another robot.
  std::int64_t episode_steps = 0;        ///< Control steps of the episodes counted.
  bool steps_ran_out = false;            ///< Not every env ended its quota of episodes.
};

/**
 * The one episode loop of the programs that play a policy on a batch (jetbot_rl_evaluate, the
 * navigation benchmark): `policy`'s mean action, step after step, its memory started over with
 * each episode, until every env has ended its first ceil(episodes / envs) episodes (a quota per
 * env, so that short episodes are not over-counted) or `max_steps` control steps ran; with
 * `episodes` 0 no episode counts and the steps run out. Outcomes count as outcomeRate() says.
 */
EpisodeTotals runEpisodes(ppo::Policy& policy, BatchedEnv& env, int episodes, int max_steps,
                          EpisodeObserver* observer = nullptr);

}  // namespace jetbot_rl
