#include "jetbot_rl/eval/episode_loop.h"

#include <vector>

#include "jetbot_rl/tasks/task.h"

namespace jetbot_rl {
void PolicyActor::act(const BatchedEnv& env, std::vector<float>& actions) {
  policy_.act(env.state().observations, env.state().images.rgb, env.numEnvs(), actions);
}

void PolicyActor::episodesBegan(const std::vector<std::uint32_t>& ids) { policy_.resetMemory(ids); }

EpisodeTotals runEpisodes(ppo::Policy& policy, BatchedEnv& env, int episodes, int max_steps,
                          EpisodeObserver* observer) {
  PolicyActor actor(policy);
  return runEpisodes(actor, env, episodes, max_steps, observer);
}

EpisodeTotals runEpisodes(EpisodeActor& actor, BatchedEnv& env, int episodes, int max_steps,
                          EpisodeObserver* observer) {
  EpisodeObserver none;
  EpisodeObserver& watch = observer ? *observer : none;
  const int envs = env.numEnvs();
  const int quota = episodes > 0 ? (episodes + envs - 1) / envs : 0;
  std::vector<int> done(envs, 0);
  std::vector<float> actions;
  EpisodeTotals totals;
  int full = 0;
  for (; totals.steps < max_steps && (quota == 0 || full < envs); ++totals.steps) {
    watch.beforeStep(env);
    actor.act(env, actions);
    // The lengths of the episodes this step may end (the reset hides them).
    const std::vector<std::uint32_t> lengths = env.state().episode_steps;
    const StepResult& r = env.step(actions);
    actor.episodesBegan(r.reset_env_ids);  // a memory starts over with each episode
    for (float x : r.rewards) totals.reward_sum += x;
    for (std::size_t i = 0; i < r.reset_env_ids.size(); ++i) {
      const std::uint32_t e = r.reset_env_ids[i];
      const int rate = outcomeRate(r.outcomes[i]);
      if (quota == 0 || done[e] >= quota || rate < 0) continue;  // rate < 0: a round's wait
      ++totals.outcomes[rate];
      if (r.outcomes[i] == static_cast<std::uint8_t>(Outcome::kCollisionMover)) {
        ++totals.mover_collisions;
      }
      if (r.outcomes[i] == static_cast<std::uint8_t>(Outcome::kCollisionRobot)) {
        ++totals.robot_collisions;
      }
      if (r.outcomes[i] == static_cast<std::uint8_t>(Outcome::kOffTrack)) ++totals.off_track;
      totals.episode_steps += lengths[e] + 1;
      ++totals.episodes;
      watch.episodeEnded(static_cast<int>(e), r.outcomes[i], lengths[e] + 1);
      if (++done[e] == quota) ++full;
    }
    watch.afterStep(env, r);
  }
  totals.steps_ran_out = quota > 0 && full < envs;
  return totals;
}

}  // namespace jetbot_rl
