#include "jetbot_rl/command_task.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

void CommandTask::resetEnv(int env, Rng& rng) {
  // Drawn even when held, so that holding does not shift the env's random stream.
  const double angle = 2.0 * M_PI * rng.uniform();
  if (!held_[env]) commands_[env] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

void CommandTask::setCommand(int env, const std::vector<double>& values, bool hold) {
  if (env < 0 || env >= static_cast<int>(commands_.size())) {
    std::ostringstream s;
    s << "command: env " << env << " is out of range [0, " << commands_.size() << ")";
    throw InputError(s.str());
  }
  if (values.size() != 2) {
    throw InputError("command of env " + std::to_string(env) + ": expected 2 values (x, y), got " +
                     std::to_string(values.size()));
  }
  const Eigen::Vector2d command(values[0], values[1]);
  if (!command.allFinite() || command.norm() < 1e-9) {
    std::ostringstream s;
    s << "command of env " << env << ": (" << command.x() << ", " << command.y()
      << ") must be a finite non-zero vector";
    throw InputError(s.str());
  }
  commands_[env] = command.normalized();
  held_[env] = hold;
}

CommandTask::Heading CommandTask::heading(int env, const RootState& state) const {
  const Eigen::Vector3d forward = state.orientation * Eigen::Vector3d::UnitX();
  const Eigen::Vector2d& c = commands_[env];
  return {forward.x() * c.x() + forward.y() * c.y(), forward.x() * c.y() - forward.y() * c.x()};
}

void CommandTask::observe(int env, const RootState& state, float* obs) const {
  const Heading h = heading(env, state);
  obs[0] = static_cast<float>(h.dot);
  obs[1] = static_cast<float>(h.cross);
  obs[2] = static_cast<float>(state.comLinearVelocityBody().x());
}

float CommandTask::reward(int env, const RootState& state) const {
  const double dot = heading(env, state).dot;
  const double forward_speed = state.comLinearVelocityBody().x();
  switch (variant_) {
    case Variant::kExp:
      return static_cast<float>(forward_speed * std::exp(dot));
    case Variant::kSum:
      return static_cast<float>(forward_speed + dot);
    case Variant::kProduct:
      return static_cast<float>(forward_speed * dot);
  }
  return 0.0f;
}

}  // namespace jetbot_rl
