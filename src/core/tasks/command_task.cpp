#include "jetbot_rl/tasks/command_task.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

CommandHeading commandHeading(const RootState& root, const Eigen::Vector2d& c) {
  const Eigen::Vector3d forward = root.orientation * Eigen::Vector3d::UnitX();
  return {forward.x() * c.x() + forward.y() * c.y(), forward.x() * c.y() - forward.y() * c.x()};
}

Eigen::Vector2d unitCommand(const std::vector<double>& values, const std::string& what) {
  if (values.size() != 2) {
    throw InputError(what + ": expected 2 values (x, y), got " + std::to_string(values.size()));
  }
  const Eigen::Vector2d command(values[0], values[1]);
  if (!command.allFinite() || command.norm() < 1e-9) {
    std::ostringstream s;
    s << what << ": (" << command.x() << ", " << command.y()
      << ") must be a finite non-zero vector";
    throw InputError(s.str());
  }
  return command.normalized();
}

void CommandObserver::observationBounds(std::vector<float>& low, std::vector<float>& high) const {
  const float inf = std::numeric_limits<float>::infinity();
  low = {-1.0f, -1.0f, -inf};
  high = {1.0f, 1.0f, inf};
}

void CommandObserver::observe(const MeasuredState& state, float* obs) const {
  const CommandHeading h = commandHeading(state.root, state.command);
  obs[0] = static_cast<float>(h.dot);
  obs[1] = static_cast<float>(h.cross);
  obs[2] = static_cast<float>(state.root.comLinearVelocityBody().x());
}

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
  commands_[env] = unitCommand(values, "command of env " + std::to_string(env));
  held_[env] = hold;
}

void CommandTask::observe(int env, const RootState& state, float* obs) const {
  MeasuredState measured;
  measured.root = state;
  measured.command = commands_[env];
  observer_.observe(measured, obs);
}

float CommandTask::reward(int env, const RootState& state) const {
  const double dot = commandHeading(state, commands_[env]).dot;
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
