// Headless demo of the batched core: all envs drive forward, one line of figures per 30 steps.
#include <chrono>
#include <cstdio>
#include <numeric>

#include "jetbot_rl/config/command_line.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  EnvProgramOptions args;
  args.num_envs = 100;
  args.steps = 600;
  args.urdf = JETBOT_RL_DEFAULT_URDF;
  if (!args.parse(argc, argv, "jetbot_rl_demo")) return 2;
  try {
    const auto batch = args.makeEnv();
    BatchedEnv& env = *batch;
    std::printf("jetbot_rl demo: %d envs, control dt %.4f s, episodes of %d steps, %d threads\n",
                env.numEnvs(), env.controlDt(), env.maxEpisodeLength() - 1, env.numThreads());
    // Env i drives with both wheels at a fraction of the limit, so speeds differ across the batch.
    std::vector<float> actions(static_cast<size_t>(env.numEnvs()) * env.actionDim());
    for (int e = 0; e < env.numEnvs(); ++e) {
      const float target = env.actionHigh()[0] * (e + 1) / env.numEnvs();
      for (int d = 0; d < env.actionDim(); ++d) actions[e * env.actionDim() + d] = target;
    }
    const auto start = std::chrono::steady_clock::now();
    std::size_t resets = 0;
    for (int s = 1; s <= args.steps; ++s) {
      const StepResult& r = env.step(actions);
      resets += r.reset_env_ids.size();
      if (s % 30 == 0 || s == args.steps) {
        const float mean_reward =
            std::accumulate(r.rewards.begin(), r.rewards.end(), 0.0f) / env.numEnvs();
        const int last = env.numEnvs() - 1;
        std::printf(
            "step %4d  t=%5.2fs  mean reward %.4f m/s  env %d v_b=(%+.3f %+.3f %+.3f) m/s  "
            "episode step %3u  resets %zu\n",
            s, s * env.controlDt(), mean_reward, last, r.observations[last * 3],
            r.observations[last * 3 + 1], r.observations[last * 3 + 2], r.episode_steps[last],
            resets);
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("done: %d control steps x %d envs in %.3f s = %.0f env steps/s\n", args.steps,
                env.numEnvs(), seconds, args.steps * env.numEnvs() / seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_demo: %s\n", e.what());
    return 1;
  }
  return 0;
}
