// jetbot_rl_bench: env steps per second of the core (BatchedEnv) in this process, random targets.
#include <chrono>
#include <cstdio>
#include <random>
#include <string>

#include "jetbot_rl/config/command_line.h"
#include "resident_memory.h"

int main(int argc, char** argv) {
  using namespace jetbot_rl;
  EnvProgramOptions args;
  args.urdf = JETBOT_RL_DEFAULT_URDF;
  if (!args.parse(argc, argv, "jetbot_rl_bench")) return 2;
  try {
    const auto batch = args.makeEnv();
    BatchedEnv& env = *batch;
    std::mt19937 gen(1);
    std::uniform_real_distribution<float> target(-20.0f, 20.0f);
    std::vector<float> actions(static_cast<size_t>(env.numEnvs()) * env.actionDim());
    for (auto& a : actions) a = target(gen);
    const int warmup = std::max(1, args.steps / 10);
    for (int s = 0; s < warmup; ++s) env.step(actions);
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < args.steps; ++s) {
      if (s % 50 == 0)
        for (auto& a : actions) a = target(gen);  // new targets every 50 steps
      env.step(actions);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double env_steps = static_cast<double>(args.steps) * env.numEnvs();
    std::printf("envs=%d threads=%d steps=%d wall_s=%.3f us_per_control_step=%.1f\n", env.numEnvs(),
                env.numThreads(), args.steps, seconds, 1e6 * seconds / args.steps);
    std::printf("rss_kib=%ld\n", residentKib());
    std::printf("env_steps_per_s=%.0f\n", env_steps / seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
