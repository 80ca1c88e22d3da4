// jetbot_rl_train_bench --trainer YAML [--trainer YAML ...] --part YAML[,YAML...] [--part ...]
// [--urdf PATH] --run-dir DIR [--task NAME] [--iterations N] [--resume CHECKPOINT] [--seed S]
// [--threads T] [--torch-threads T]: the trainer's in-process training (jetbot_ppo_trainer
// env_in_process) without ROS, for training experiments on hosts that have none
// (docs/performance.md, "Training without ROS"). --trainer: the trainer's parameter files (PPO and
// run fields; later files win);
// --part: one env of the batch, from its parameter files in the order jetbot_env.launch loads them
// (a mix: one --part per part, stepped as one batch in order, part k reseeded with seed +
// k x 2^32 as the trainer does); --task, --threads: every part's task and stepping threads over
// the files'. Prints the runner's progress lines and the final figures; SIGINT
// or SIGTERM ends the run as Ctrl-C ends the trainer's (its state saved: --resume continues it).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "jetbot_rl/config/command_line.h"
#include "jetbot_rl/config/file_checks.h"
#include "jetbot_rl/config/yaml_flatten.h"
#include "jetbot_rl/env/env_setup.h"
#include "jetbot_rl/env/local_vec_env.h"
#include "jetbot_rl/env/multi_vec_env.h"
#include "jetbot_rl/ppo/freed_memory.h"
#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/ppo/ppo_config.h"
#include "jetbot_rl/ppo/runner.h"

namespace {

using namespace jetbot_rl;

std::atomic<bool> stop_requested{false};

/// The env, which throws Interrupted at the next step once SIGINT or SIGTERM came (the runner
/// then saves and returns, as the trainer does on Ctrl-C).
class StoppableVecEnv : public VecEnv {
 public:
  explicit StoppableVecEnv(std::unique_ptr<VecEnv> env) : env_(std::move(env)) {}
  const BatchSpec& spec() const override { return env_->spec(); }
  const StepResult& reset(std::int64_t seed,
                          const std::vector<std::uint32_t>& episode_steps) override {
    return env_->reset(seed, episode_steps);
  }
  void stepAsync(const std::vector<float>& actions) override {
    if (stop_requested) throw Interrupted("stopped by a signal");
    env_->stepAsync(actions);
  }
  const StepResult& stepWait() override { return env_->stepWait(); }

 private:
  std::unique_ptr<VecEnv> env_;
};

/// Splits "a,b,c" into its non-empty pieces.
std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> pieces;
  std::istringstream s(text);
  for (std::string piece; std::getline(s, piece, ',');) {
    if (!piece.empty()) pieces.push_back(piece);
  }
  return pieces;
}

/// The trainer's fields that the files set, in order (later files win); each file read once.
void readTrainerFiles(const std::vector<std::string>& paths, ppo::PpoConfig& ppo_config,
                      ppo::RunnerOptions& options) {
  for (const std::string& path : paths) {
    if (const std::string problem = fileProblem(path); !problem.empty()) {
      throw ConfigError("cannot read the parameter file " + path + ": it " + problem);
    }
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw ConfigError("cannot read the parameter file " + path);
    try {
      const std::string fields = flattenYaml(text.str());
      fieldsFromYaml(fields, ppo_config);
      fieldsFromYaml(fields, options);
    } catch (const ConfigError& e) {
      throw ConfigError(path + ": " + e.what());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> trainer_files, parts;
  std::string urdf = JETBOT_RL_DEFAULT_LIDAR_URDF, run_dir, resume, task;
  long long iterations = 0, seed = -1;
  int threads = 0, torch_threads = 1;
  const auto take = [&](const std::string& option, const std::string& value, std::string& error) {
    if (option == "--trainer") {
      trainer_files.push_back(value);
    } else if (option == "--part") {
      parts.push_back(value);
    } else if (option == "--urdf") {
      urdf = value;
    } else if (option == "--run-dir") {
      run_dir = value;
    } else if (option == "--task") {
      task = value;
    } else if (option == "--resume") {
      resume = value;
    } else if (option == "--iterations") {
      parseWholeNumber(option, value, 1, 1000000000LL, iterations, error);
    } else if (option == "--seed") {
      parseWholeNumber(option, value, 0, 1000000000000LL, seed, error);
    } else if (option == "--threads") {
      parseWholeNumber(option, value, 0, 1024, threads, error);
    } else if (option == "--torch-threads") {
      parseWholeNumber(option, value, 1, 256, torch_threads, error);
    } else {
      return false;
    }
    return true;
  };
  std::string error;
  if (parseOptions(argc, argv, take, error) &&
      (trainer_files.empty() || parts.empty() || run_dir.empty())) {
    error = "--trainer, --part and --run-dir are required";
  }
  if (!error.empty()) {
    std::fprintf(
        stderr,
        "jetbot_rl_train_bench: %s\nusage: jetbot_rl_train_bench --trainer YAML ... "
        "--part YAML[,YAML...] ... --run-dir DIR [--urdf PATH] [--task NAME] [--iterations N] "
        "[--resume CHECKPOINT] [--seed S] [--threads T] [--torch-threads T]\n",
        error.c_str());
    return 2;
  }
  try {
    ppo::PpoConfig ppo_config;
    ppo::RunnerOptions options;
    readTrainerFiles(trainer_files, ppo_config, options);
    if (seed >= 0) ppo_config.seed = seed;
    if (iterations > 0) options.iterations = iterations;
    options.run_dir = run_dir;
    options.resume = resume;
    if (!resume.empty() && std::filesystem::is_directory(resume)) {
      options.resume = resume + "/checkpoints/latest.pt";
    }
    // Refused before anything is created: a bad value or part leaves no run directory behind.
    ppo::validate(ppo_config);
    validateFields(options);
    ppo::setTorchThreads(torch_threads);
    const std::string heap = ppo::keepFreedMemory();
    if (!heap.empty()) std::fprintf(stderr, "warning: %s\n", heap.c_str());

    const RobotModelConstPtr robot =
        RobotModel::fromUrdfFile(urdf, EnvProgramOptions::packagePathResolver());
    std::vector<std::unique_ptr<VecEnv>> envs;
    std::vector<std::string> names;
    for (const std::string& part : parts) {
      EnvSetup setup;
      readEnvSetupFiles(splitList(part), setup);
      if (!task.empty()) fieldsFromYaml("task: " + task, setup);
      if (threads > 0) setup.env.num_threads = threads;
      envs.push_back(std::make_unique<LocalVecEnv>(makeEnv(robot, setup)));
      names.push_back(part);
    }
    StoppableVecEnv env(envs.size() == 1 ? std::move(envs.front())
                                         : std::make_unique<MultiVecEnv>(std::move(envs), names));
    std::signal(SIGINT, [](int) { stop_requested = true; });
    std::signal(SIGTERM, [](int) { stop_requested = true; });
    std::filesystem::create_directories(run_dir);
    ppo::OnPolicyRunner runner(env, ppo_config, options);
    const ppo::TrainingSummary summary = runner.learn();
    std::cout << "final figures:\n" << ppo::describeSummary(summary) << std::endl;
    if (!summary.error.empty()) {
      std::fprintf(stderr, "jetbot_rl_train_bench: training failed: %s\n", summary.error.c_str());
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jetbot_rl_train_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
