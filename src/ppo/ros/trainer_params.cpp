#include "jetbot_rl/ppo/ros/trainer_params.h"

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/param_reader.h"

namespace jetbot_rl {
namespace ppo {
namespace {

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y%m%d_%H%M%S", &tm);
  return buf;
}

}  // namespace

void readPpoParams(const ros::NodeHandle& pnh, PpoConfig& config) {
  visitFields(config, [&pnh](const char* name, auto& value) { readParam(pnh, name, value); });
}

std::string defaultRunRoot() {
  namespace fs = std::filesystem;
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home && *ros_home) {
    return (fs::path(ros_home) / "jetbot_rl").string();
  }
  const char* home = std::getenv("HOME");
  return (fs::path(home && *home ? home : ".") / ".ros" / "jetbot_rl").string();
}

TrainerParams loadTrainerParams(const ros::NodeHandle& pnh) {
  namespace fs = std::filesystem;
  TrainerParams p;
  readPpoParams(pnh, p.ppo);
  readParam(pnh, "iterations", p.iterations);
  readParam(pnh, "run_dir", p.run_dir);
  readParam(pnh, "resume", p.resume);
  readParam(pnh, "env", p.env);
  readParam(pnh, "save_interval", p.save_interval);
  readParam(pnh, "step_timeout", p.step_timeout);
  readParam(pnh, "torch_threads", p.torch_threads);
  readParam(pnh, "target_reward", p.target_reward);
  readParam(pnh, "obs_stats_from_step", p.obs_stats_from_step);

  validate(p.ppo);
  if (p.iterations < 1) throwInvalid("iterations", p.iterations, "must be >= 1");
  if (p.env.empty()) throwInvalid("env", "''", "must name the jetbot_env node, e.g. /jetbot_env");
  if (p.save_interval < 1) throwInvalid("save_interval", p.save_interval, "must be >= 1");
  if (!std::isfinite(p.step_timeout) || p.step_timeout <= 0.0) {
    throwInvalid("step_timeout", p.step_timeout, "must be a positive number of seconds");
  }
  if (p.torch_threads < 1 || p.torch_threads > 256) {
    throwInvalid("torch_threads", p.torch_threads, "must be in [1, 256]");
  }
  if (!std::isfinite(p.target_reward))
    throwInvalid("target_reward", p.target_reward, "must be finite");
  if (p.obs_stats_from_step < -1) {
    throwInvalid("obs_stats_from_step", p.obs_stats_from_step,
                 "must be -1 (second half of an episode) or an episode step >= 0");
  }

  if (!p.resume.empty()) {
    // A run directory stands for its latest checkpoint.
    if (fs::is_directory(p.resume)) p.resume = (fs::path(p.resume) / "checkpoints/latest.pt");
    if (!fs::is_regular_file(p.resume)) {
      throwInvalid("resume", "'" + p.resume + "'", "is not a checkpoint file or run directory");
    }
    // By default the resumed run continues in its own directory (parent of checkpoints/).
    if (p.run_dir.empty()) {
      p.run_dir = fs::absolute(p.resume).parent_path().parent_path().string();
    }
  }
  if (p.run_dir.empty()) {
    p.run_dir = (fs::path(defaultRunRoot()) / (timestamp() + "_seed" + std::to_string(p.ppo.seed)))
                    .string();
  }
  std::error_code ec;
  fs::create_directories(p.run_dir, ec);
  if (ec || !fs::is_directory(p.run_dir)) {
    throwInvalid("run_dir", "'" + p.run_dir + "'", "cannot be created: " + ec.message());
  }
  return p;
}

std::string describeTrainerParams(const TrainerParams& p, bool with_ppo) {
  std::ostringstream s;
  s << "iterations: " << p.iterations << "\nrun_dir: " << p.run_dir << "\nresume: '" << p.resume
    << "'\nenv: " << p.env << "\nsave_interval: " << p.save_interval
    << "\nstep_timeout: " << p.step_timeout << "  # s\ntorch_threads: " << p.torch_threads
    << "\ntarget_reward: " << p.target_reward
    << "  # m/s\nobs_stats_from_step: " << p.obs_stats_from_step << "  # control steps\n";
  if (with_ppo) s << toYaml(p.ppo);
  return s.str();
}

}  // namespace ppo
}  // namespace jetbot_rl
