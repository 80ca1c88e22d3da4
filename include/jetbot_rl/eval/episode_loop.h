#pragma once

#include <cstdint>
#include <vector>

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

/// Several observers as one, each called in the order added.
class EpisodeObservers : public EpisodeObserver {
 public:
  /// Adds `observer` (not owned; null is ignored).
  void add(EpisodeObserver* observer) {
    if (observer) observers_.push_back(observer);
  }
  void beforeStep(const BatchedEnv& env) override {
    for (EpisodeObserver* o : observers_) o->beforeStep(env);
  }
  void episodeEnded(int env, std::uint8_t outcome, std::uint32_t steps) override {
    for (EpisodeObserver* o : observers_) o->episodeEnded(env, outcome, steps);
  }
  void afterStep(const BatchedEnv& env, const StepResult& result) override {
    for (EpisodeObserver* o : observers_) o->afterStep(env, result);
  }

 private:
  std::vector<EpisodeObserver*> observers_;
};

/// What an episode loop counted.
struct EpisodeTotals {
  int steps = 0;                         ///< Control steps run.
  double reward_sum = 0.0;               ///< Over every env and step.
  std::int64_t episodes = 0;             ///< Episodes counted.
  std::int64_t outcomes[3] = {0, 0, 0};  ///< Per outcomeRate(): time-out, success, collision.
  std::int64_t mover_collisions = 0;     ///< Of the collisions: with a mover.
  std::int64_t robot_collisions = 0;     ///< Of the collisions: with another robot.
  std::int64_t off_track = 0;            ///< Of the failures: off the tape (road following).
  std::int64_t episode_steps = 0;        ///< Control steps of the episodes counted.
  bool steps_ran_out = false;            ///< Not every env ended its quota of episodes.
};

/// What acts in an episode loop: a policy's mean action, or a classical planner (DwaActor).
class EpisodeActor {
 public:
  virtual ~EpisodeActor() = default;
  /// Every env's action for the state `env` is in (numEnvs() x action_dim).
  virtual void act(const BatchedEnv& env, std::vector<float>& actions) = 0;
  /// Envs `ids` began new episodes (a memory starts over).
  virtual void episodesBegan(const std::vector<std::uint32_t>& /*ids*/) {}
};

/// A policy's mean action, its memory started over with each episode.
class PolicyActor : public EpisodeActor {
 public:
  explicit PolicyActor(ppo::Policy& policy) : policy_(policy) {}
  void act(const BatchedEnv& env, std::vector<float>& actions) override;
  void episodesBegan(const std::vector<std::uint32_t>& ids) override;

 private:
  ppo::Policy& policy_;
};

/**
 * The one episode loop of the programs that play a policy on a batch (jetbot_rl_evaluate, the
 * navigation benchmark): `actor`'s action, step after step, told of each new episode, until every
 * env has ended its first ceil(episodes / envs) episodes (a quota per env, so that short episodes
 * are not over-counted) or `max_steps` control steps ran; with `episodes` 0 no episode counts and
 * the steps run out. Outcomes count as outcomeRate() says.
 */
EpisodeTotals runEpisodes(EpisodeActor& actor, BatchedEnv& env, int episodes, int max_steps,
                          EpisodeObserver* observer = nullptr);
/// The same with `policy`'s mean action, its memory started over with each episode.
EpisodeTotals runEpisodes(ppo::Policy& policy, BatchedEnv& env, int episodes, int max_steps,
                          EpisodeObserver* observer = nullptr);

}  // namespace jetbot_rl
