#include "jetbot_rl/env/env_config.h"

#include <cmath>
#include <thread>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/robot_model.h"

namespace jetbot_rl {

namespace {

/// Several robots share one world: its obstacles must be the same for all of them (its movers
/// are: they walk per world), and each needs a start of its own.
void checkTeamRules(const EnvConfig& config) {
  const int k = config.team.robots_per_env;
  const bool swap = config.team.swap_radius > 0.0;
  if (k == 1 && config.team.rounds) {
    throwInvalid("rounds", std::string("true"),
                 "needs robots_per_env > 1: rounds are of several robots");
  }
  if (k == 1 && !swap) return;
  // Name the field that asked for it.
  const auto refuse = [&](const std::string& why) {
    if (k > 1) throwInvalid("robots_per_env", k, why);
    throwInvalid("swap_radius", config.team.swap_radius, why);
  };
  const long long rows = static_cast<long long>(config.num_envs) * k;
  if (rows > 1000000)
    refuse("num_envs x robots_per_env = " + std::to_string(rows) + ": must be <= 1000000");
  const WorldConfig& w = config.world;
  if (!w.enabled()) refuse("needs a world: give world/arena_size, world/map or world/gazebo_world");
  if ((w.num_boxes + w.num_cylinders > 0 || !w.families.empty()) && swap) {
    throwInvalid("swap_radius", config.team.swap_radius,
                 "needs world/num_boxes and world/num_cylinders 0 and world/families []: the "
                 "circle's points and their opposites must stay free");
  }
  if (!w.random_start && !swap) {
    refuse(
        "needs world/random_start true or swap_radius > 0: K robots cannot all start at "
        "world/spawn");
  }
}

}  // namespace

void checkFieldRules(const EnvConfig& config) {
  checkFieldRules(config.world);
  checkFieldRules(config.scan);
  checkFieldRules(config.camera);
  checkFieldRules(config.speed_limit);
  if (config.movers.count() > 0 && !config.world.enabled()) {
    throwInvalid(config.movers.num_people > 0 ? "movers/num_people" : "movers/num_carts",
                 config.movers.count(),
                 "movers walk in a world: give world/arena_size, world/map or world/gazebo_world");
  }
  checkTeamRules(config);
  if (config.twist_reverse_speed < 0.0 && config.twist_reverse_speed != -1.0) {
    throwInvalid("twist_reverse_speed", config.twist_reverse_speed,
                 "must be -1 (as fast as forwards) or >= 0 m/s");
  }
  if (config.twist_reverse_speed != -1.0 && config.action_space != ActionSpace::kTwist) {
    throwInvalid("twist_reverse_speed", config.twist_reverse_speed,
                 "bounds twist actions: it needs action_space twist");
  }
  const SpeedLimitConfig& limit = config.speed_limit;
  if (limit.enabled || limit.deployed) {
    const char* field = limit.enabled ? "speed_limit/enabled" : "speed_limit/deployed";
    if (config.action_space != ActionSpace::kTwist) {
      throwInvalid(field, "true", "caps a twist's forward v: it needs action_space twist");
    }
    if (!config.scan.enabled) {
      throwInvalid(field, "true", "reads the scan ahead: it needs scan/enabled");
    }
  }
  const double steps = config.episode_length_s / config.controlDt();
  if (steps < 2.0 || steps > 1e9) {
    throwInvalid("episode_length_s", config.episode_length_s,
                 "must last between 2 and 1e9 control steps of physics_dt * decimation");
  }
}

void EnvConfig::validate() const { validateConfig(*this); }

std::vector<std::string> resolvedDofNames(const EnvConfig& config, const RobotModel& robot) {
  if (!config.dof_names.empty()) return config.dof_names;
  const auto& plugin = robot.gazebo().diff_drive;
  if (plugin && !plugin->left_joint.empty() && !plugin->right_joint.empty()) {
    return {plugin->left_joint, plugin->right_joint};
  }
  return {"left_wheel_joint", "right_wheel_joint"};
}

int EnvConfig::maxEpisodeLength() const {
  return static_cast<int>(std::ceil(episode_length_s / controlDt()));
}

int EnvConfig::resolvedThreads() const {
  if (num_threads > 0) return num_threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace jetbot_rl
