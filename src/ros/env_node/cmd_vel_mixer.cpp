#include "jetbot_rl/ros/env_node/cmd_vel_mixer.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

CmdVelMixer::CmdVelMixer(DiffDrive drive, int envs, double timeout, bool twist_actions)
    : drive_(std::move(drive)),
      twist_actions_(twist_actions),
      timeout_(timeout),
      commands_(static_cast<std::size_t>(envs)) {}

void CmdVelMixer::set(int env, const geometry_msgs::Twist& msg, SteadyTime received) {
  if (env < 0 || env >= envs()) {
    throw InputError("cmd_vel for env " + std::to_string(env) + ": only envs 0.." +
                     std::to_string(envs() - 1) + " take cmd_vel (robot_view_envs)");
  }
  const std::pair<const char*, double> components[] = {
      {"linear.x", msg.linear.x},   {"linear.y", msg.linear.y},   {"linear.z", msg.linear.z},
      {"angular.x", msg.angular.x}, {"angular.y", msg.angular.y}, {"angular.z", msg.angular.z}};
  for (const auto& [name, value] : components) {
    if (!std::isfinite(value)) {
      std::ostringstream s;
      s << name << " = " << value << " is not finite; the previous command stays";
      throw InputError(s.str());
    }
  }
  const std::array<double, 2> action = twist_actions_
                                           ? std::array<double, 2>{msg.linear.x, msg.angular.z}
                                           : drive_.wheelTargets({msg.linear.x, msg.angular.z});
  Command& c = commands_[static_cast<std::size_t>(env)];
  c.targets = {static_cast<float>(action[0]), static_cast<float>(action[1])};
  c.received = received;
  c.valid = true;
}

bool CmdVelMixer::anyFresh(SteadyTime now) const {
  for (const Command& c : commands_) {
    if (fresh(c, now)) return true;
  }
  return false;
}

void CmdVelMixer::apply(SteadyTime now, float* targets, std::size_t count) const {
  for (std::size_t e = 0; e < commands_.size() && 2 * e + 1 < count; ++e) {
    if (!fresh(commands_[e], now)) continue;
    targets[2 * e] = commands_[e].targets[0];
    targets[2 * e + 1] = commands_[e].targets[1];
  }
}

}  // namespace jetbot_rl
