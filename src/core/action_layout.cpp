#include "action_layout.h"

#include <cmath>

#include "jetbot_rl/errors.h"

namespace jetbot_rl {

ActionLayout makeActionLayout(const RobotModel& robot, const EnvConfig& config,
                              const std::vector<double>& wheel_limits) {
  ActionLayout a;
  if (config.action_space != ActionSpace::kTwist) {
    for (double limit : wheel_limits) {
      a.low.push_back(static_cast<float>(-limit));
      a.high.push_back(static_cast<float>(limit));
    }
    a.names = config.dof_names;
    return a;
  }
  try {
    a.drive = std::make_unique<DiffDrive>(DiffDrive::fromRobot(
        robot, config.dof_names, wheel_limits, config.wheel_radius, config.wheel_separation));
  } catch (const Error& e) {
    throw ConfigError(std::string("invalid action_space = twist: it needs a differential drive: ") +
                      e.what());
  }
  // The fastest straight line and turn on the spot the wheels allow.
  const double v = std::abs(a.drive->bodyTwist({wheel_limits[0], wheel_limits[1]}).linear);
  const double w = std::abs(a.drive->bodyTwist({-wheel_limits[0], wheel_limits[1]}).angular);
  if (config.twist_reverse_speed > v) {
    throwInvalid(
        "twist_reverse_speed", config.twist_reverse_speed,
        "must not exceed the fastest straight v the wheels allow (" + std::to_string(v) + " m/s)");
  }
  const double reverse = config.twist_reverse_speed < 0.0 ? v : config.twist_reverse_speed;
  a.low = {static_cast<float>(-reverse), static_cast<float>(-w)};
  a.high = {static_cast<float>(v), static_cast<float>(w)};
  a.names = {"linear_x", "angular_z"};
  return a;
}

}  // namespace jetbot_rl
