#include "jetbot_rl/ppo/ros/trainer_params.h"

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {
namespace ppo {
namespace {

const char* typeName(bool) { return "a bool"; }
const char* typeName(int) { return "an integer"; }
const char* typeName(double) { return "a number"; }
const char* typeName(const std::string&) { return "a string"; }
const char* typeName(const std::vector<int>&) { return "a list of integers"; }

/// Reads ~name into `value` when it is set; throws ConfigError when it has the wrong type.
template <typename T>
void readParam(const ros::NodeHandle& pnh, const std::string& name, T& value) {
  if (!pnh.hasParam(name)) return;
  if (pnh.getParam(name, value)) return;
  XmlRpc::XmlRpcValue raw;
  pnh.getParam(name, raw);
  std::ostringstream s;
  s << "invalid " << name << " = " << raw << ": must be " << typeName(value);
  throw ConfigError(s.str());
}

template <typename T>
[[noreturn]] void fail(const std::string& name, const T& value, const std::string& rule) {
  std::ostringstream s;
  s << "invalid " << name << " = " << value << ": " << rule;
  throw ConfigError(s.str());
}

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
  if (p.iterations < 1) fail("iterations", p.iterations, "must be >= 1");
  if (p.env.empty()) fail("env", "''", "must name the jetbot_env node, e.g. /jetbot_env");
  if (p.save_interval < 1) fail("save_interval", p.save_interval, "must be >= 1");
  if (!std::isfinite(p.step_timeout) || p.step_timeout <= 0.0) {
    fail("step_timeout", p.step_timeout, "must be a positive number of seconds");
  }
  if (p.torch_threads < 1 || p.torch_threads > 256) {
    fail("torch_threads", p.torch_threads, "must be in [1, 256]");
  }
  if (!std::isfinite(p.target_reward)) fail("target_reward", p.target_reward, "must be finite");
  if (p.obs_stats_from_step < -1) {
    fail("obs_stats_from_step", p.obs_stats_from_step,
         "must be -1 (second half of an episode) or an episode step >= 0");
  }

  if (!p.resume.empty()) {
    // A run directory stands for its latest checkpoint.
    if (fs::is_directory(p.resume)) p.resume = (fs::path(p.resume) / "checkpoints/latest.pt");
    if (!fs::is_regular_file(p.resume)) {
      fail("resume", "'" + p.resume + "'", "is not a checkpoint file or run directory");
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
    fail("run_dir", "'" + p.run_dir + "'", "cannot be created: " + ec.message());
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
