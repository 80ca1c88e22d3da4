// MuJoCo counterpart of jetbot_rl_bench, for the speed comparison in docs/performance.md: the same
// robot (bench/jetbot_mujoco.xml), one mjData per env, the same loop (random wheel targets redrawn
// every 50 control steps, 2 physics steps of 1/120 s per control step, episodes reset after 299
// steps, body-frame velocity observation and its norm as reward), stepped in lockstep by T threads
// over contiguous blocks. Built only with -DJETBOT_RL_MUJOCO_BENCH=ON (needs libmujoco-dev).
//   mujoco_bench --num-envs N --steps S --threads T --model bench/jetbot_mujoco.xml
#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "resident_memory.h"

namespace {

constexpr int kDecimation = 2;
constexpr int kLastEpisodeStep = 299;  // jetbot_rl: max_episode_length - 1

/// Blocking barrier for a fixed number of threads (the hand-off of jetbot_rl's thread pool).
class Barrier {
 public:
  explicit Barrier(int count) : count_(count) {}
  void wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    const unsigned long generation = generation_;
    if (++arrived_ == count_) {
      arrived_ = 0;
      ++generation_;
      cv_.notify_all();
      return;
    }
    cv_.wait(lock, [&] { return generation_ != generation; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  int count_;
  int arrived_ = 0;
  unsigned long generation_ = 0;
};

struct Args {
  int envs = 1024;
  int steps = 1000;
  int threads = 1;
  std::string model = "bench/jetbot_mujoco.xml";
};

bool parse(int argc, char** argv, Args& args) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    const char* value = argv[i + 1];
    if (option == "--model") {
      args.model = value;
      continue;
    }
    int* target = option == "--num-envs"  ? &args.envs
                  : option == "--steps"   ? &args.steps
                  : option == "--threads" ? &args.threads
                                          : nullptr;
    char* end = nullptr;
    const long number = std::strtol(value, &end, 10);
    if (!target || *end != '\0' || number < 1 || number > 100000000) {
      std::fprintf(stderr, "mujoco_bench: invalid %s %s\n", option.c_str(), value);
      return false;
    }
    *target = static_cast<int>(number);
  }
  return argc % 2 == 1;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, args)) {
    std::fprintf(stderr,
                 "usage: mujoco_bench [--num-envs N] [--steps S] [--threads T] [--model MJCF]\n");
    return 2;
  }
  char error[1000] = "";
  mjModel* model = mj_loadXML(args.model.c_str(), nullptr, error, sizeof error);
  if (!model) {
    std::fprintf(stderr, "mujoco_bench: %s: %s\n", args.model.c_str(), error);
    return 1;
  }
  const int n = args.envs;
  const int workers = std::max(1, std::min(args.threads, n));
  const int nu = model->nu;
  std::vector<mjData*> data(n, nullptr);
  std::vector<int> episode_steps(n, 0);
  std::vector<float> observations(static_cast<size_t>(n) * 3), rewards(n);
  std::vector<double> targets(static_cast<size_t>(n) * nu);
  auto first = [&](int w) { return static_cast<int>(static_cast<long long>(w) * n / workers); };

  auto step_block = [&](int w) {
    for (int e = first(w); e < first(w + 1); ++e) {
      mjData* d = data[e];
      for (int u = 0; u < nu; ++u) d->ctrl[u] = targets[static_cast<size_t>(e) * nu + u];
      for (int k = 0; k < kDecimation; ++k) mj_step(model, d);
      if (++episode_steps[e] >= kLastEpisodeStep) {
        mj_resetData(model, d);
        episode_steps[e] = 0;
      }
      // Body-frame linear velocity of the free joint (world-frame qvel[0:3], orientation
      // qpos[3:7]).
      mjtNum inverse[4], v[3];
      mju_negQuat(inverse, d->qpos + 3);
      mju_rotVecQuat(v, d->qvel, inverse);
      for (int i = 0; i < 3; ++i)
        observations[static_cast<size_t>(e) * 3 + i] = static_cast<float>(v[i]);
      rewards[e] = static_cast<float>(mju_norm3(v));
    }
  };

  // Each thread makes its own block's mjData, as jetbot_rl's workers make their worlds.
  Barrier barrier(workers);
  int total_steps = 0;  // set before the threads start
  const int warmup = std::max(1, args.steps / 10);
  std::mt19937 gen(1);
  std::uniform_real_distribution<float> target(-20.0f, 20.0f);
  auto draw = [&] {
    for (auto& t : targets) t = target(gen);
  };
  std::chrono::steady_clock::time_point start;
  total_steps = warmup + args.steps;
  draw();
  auto run = [&](int w) {
    for (int e = first(w); e < first(w + 1); ++e) data[e] = mj_makeData(model);
    barrier.wait();
    for (int s = 0; s < total_steps; ++s) {
      if (w == 0) {  // the caller's work between steps: new targets, the clock
        if (s == warmup) start = std::chrono::steady_clock::now();
        if (s >= warmup && (s - warmup) % 50 == 0) draw();
      }
      barrier.wait();
      step_block(w);
      barrier.wait();
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(run, w);
  run(0);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (auto& t : threads) t.join();
  const double env_steps = static_cast<double>(args.steps) * n;
  std::printf("mujoco %s envs=%d threads=%d steps=%d wall_s=%.3f mjdata_bytes=%ld\n",
              mj_versionString(), n, workers, args.steps, seconds,
              static_cast<long>(data[0]->nbuffer) + static_cast<long>(data[0]->nstack) * 8);
  std::printf("rss_kib=%ld\n", jetbot_rl::residentKib());
  std::printf("env_steps_per_s=%.0f\n", env_steps / seconds);
  for (mjData* d : data) mj_deleteData(d);
  mj_deleteModel(model);
  return 0;
}
