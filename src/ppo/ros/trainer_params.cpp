#include "jetbot_rl/ppo/ros/trainer_params.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/param_reader.h"

namespace jetbot_rl {
namespace ppo {

std::string defaultRunRoot() {
  namespace fs = std::filesystem;
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home && *ros_home) {
    return (fs::path(ros_home) / "jetbot_rl").string();
  }
  const char* home = std::getenv("HOME");
  return (fs::path(home && *home ? home : ".") / ".ros" / "jetbot_rl").string();
}

namespace {

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y%m%d_%H%M%S", &tm);
  return buf;
}

/// resume: a run directory stands for its latest checkpoint; run_dir: resume's run by default,
/// else a new one named after the time and seed; created.
void resolveRunDir(TrainerConfig& c) {
  namespace fs = std::filesystem;
  std::string& resume = c.trainer.run.resume;
  std::string& run_dir = c.trainer.run.run_dir;
  if (!resume.empty()) {
    // A run directory stands for its latest checkpoint.
    if (fs::is_directory(resume)) resume = (fs::path(resume) / "checkpoints/latest.pt");
    if (!fs::is_regular_file(resume)) {
      throwInvalid("resume", "'" + resume + "'", "is not a checkpoint file or run directory");
    }
    // By default the resumed run continues in its own directory (parent of checkpoints/).
    if (run_dir.empty()) run_dir = fs::absolute(resume).parent_path().parent_path().string();
  }
  if (run_dir.empty()) {
    run_dir = (fs::path(defaultRunRoot()) / (timestamp() + "_seed" + std::to_string(c.ppo.seed)))
                  .string();
  }
  std::error_code ec;
  fs::create_directories(run_dir, ec);
  if (ec || !fs::is_directory(run_dir)) {
    throwInvalid("run_dir", "'" + run_dir + "'", "cannot be created: " + ec.message());
  }
}

}  // namespace

std::optional<TrainerConfig> loadTrainerConfig(const ros::NodeHandle& pnh) {
  return loadParams<TrainerConfig>(pnh, resolveRunDir);
}

}  // namespace ppo
}  // namespace jetbot_rl
