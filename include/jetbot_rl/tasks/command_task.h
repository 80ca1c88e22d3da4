#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/tasks/task_observer.h"

namespace jetbot_rl {

/// The command task's observation: [dot(forward, command), cross(forward, command).z, v_body.x],
/// forward being the body +x axis in the measured frame.
class CommandObserver : public TaskObserver {
 public:
  std::vector<std::string> observationNames() const override {
    return {"forward_dot_command", "forward_cross_command_z", "lin_vel_b_x"};
  }
  void observationBounds(std::vector<float>& low, std::vector<float>& high) const override;
  bool takesCommand() const override { return true; }
  void observe(const MeasuredState& state, float* obs) const override;
};

/// cos and sin of the angle from the root's forward (body +x) axis to `command` (a unit vector
/// in the same frame), counter-clockwise positive.
struct CommandHeading {
  double dot;
  double cross;
};
CommandHeading commandHeading(const RootState& root, const Eigen::Vector2d& command);

/// `values` (x, y) as a unit command; InputError naming `what` and the values when there are not
/// two or they are zero or not finite.
Eigen::Vector2d unitCommand(const std::vector<double>& values, const std::string& what);

/**
 * The walkthrough's command-following task: every reset draws a random unit command in the ground
 * plane from the env's seeded stream; the robot should turn towards it and drive along it.
 *
 * Observation: CommandObserver's. Reward by `Variant`: kExp v_x * exp(dot) (the walkthrough's
 * final choice), kSum v_x + dot (naive), kProduct v_x * dot (learns to reverse).
 */
class CommandTask : public Task, public Commandable, public ArrowDrawing {
 public:
  enum class Variant { kExp, kSum, kProduct };

  explicit CommandTask(Variant variant = Variant::kExp) : variant_(variant) {}

  std::string name() const override { return "command"; }
  const TaskObserver& observer() const override { return observer_; }
  void resize(int num_envs) override {
    commands_.assign(num_envs, Eigen::Vector2d::UnitX());
    held_.assign(num_envs, 0);
  }
  void resetEnv(int env, Rng& rng) override;
  void observe(int env, const RootState& state, float* obs) const override;
  float reward(int env, const RootState& state) const override;

  int commandDim() const override { return 2; }
  /// Sets env `env`'s command (x, y, normalised); InputError for a bad env id or a zero or
  /// non-finite vector. Kept until the env's next reset, or across resets when `hold`.
  void setCommand(int env, const std::vector<double>& command, bool hold) override;
  std::vector<std::string> arrowNames() const override { return {"command"}; }
  Eigen::Vector2d arrowDirection(int env, int) const override { return command(env); }

  Variant variant() const { return variant_; }
  /// Unit command of env `env` in the world (= env) frame's x-y plane.
  const Eigen::Vector2d& command(int env) const { return commands_.at(env); }
  /// setCommand() with a 2-D vector.
  void setCommand(int env, const Eigen::Vector2d& command, bool hold = false) {
    setCommand(env, std::vector<double>{command.x(), command.y()}, hold);
  }
  /// True when env `env`'s command is held across resets.
  bool held(int env) const { return held_.at(env) != 0; }

 private:
  Variant variant_;
  CommandObserver observer_;
  std::vector<Eigen::Vector2d> commands_;
  std::vector<unsigned char> held_;  // per env; not vector<bool>: envs are written concurrently
};

inline const EnumNameList<CommandTask::Variant>& enumNames(CommandTask::Variant) {
  static const EnumNameList<CommandTask::Variant> names{
      {CommandTask::Variant::kExp, "exp"},
      {CommandTask::Variant::kSum, "sum"},
      {CommandTask::Variant::kProduct, "product"}};
  return names;
}

}  // namespace jetbot_rl
