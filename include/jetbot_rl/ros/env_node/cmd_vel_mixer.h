#pragma once

#include <geometry_msgs/Twist.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <vector>

#include "jetbot_rl/robot/diff_drive.h"

namespace jetbot_rl {

/**
 * Realtime mode's cmd_vel: the latest valid Twist of each robot env, converted by DiffDrive into
 * that env's wheel targets, overrides the env's WheelTargets while it is at most `timeout` old.
 * Not thread-safe (EnvServer serialises the calls).
 */
class CmdVelMixer {
 public:
  using SteadyTime = std::chrono::steady_clock::time_point;

  /// Commands for envs 0..envs-1 of a batch whose action_dim is 2 (the drive's dofs, or with
  /// `twist_actions` the env's (v, omega) actions, which take a command as it is); `timeout`
  /// [s, wall].
  CmdVelMixer(DiffDrive drive, int envs, double timeout, bool twist_actions = false);

  /// Converts `msg` into env `env`'s wheel targets [rad/s], received at `received`. Throws
  /// InputError naming the component when any of the six is NaN or infinite (or the env is
  /// unknown); the previous command then stays, with its own age. Only linear.x and angular.z
  /// drive; the other components are ignored.
  void set(int env, const geometry_msgs::Twist& msg, SteadyTime received);
  /// True when some env's command is at most `timeout` old at `now`.
  bool anyFresh(SteadyTime now) const;
  /// Overwrites the two targets of every env with a fresh command in `targets` (num_envs x 2
  /// [rad/s], row-major; `count` values).
  void apply(SteadyTime now, float* targets, std::size_t count) const;

  int envs() const { return static_cast<int>(commands_.size()); }
  const DiffDrive& drive() const { return drive_; }

 private:
  struct Command {
    std::array<float, 2> targets{};  // [rad/s] in dof order
    SteadyTime received;
    bool valid = false;
  };

  bool fresh(const Command& c, SteadyTime now) const {
    return c.valid && now - c.received <= timeout_;
  }

  DiffDrive drive_;
  bool twist_actions_;
  std::chrono::duration<double> timeout_;
  std::vector<Command> commands_;
};

}  // namespace jetbot_rl
