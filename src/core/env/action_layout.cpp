#include "env/action_layout.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "jetbot_rl/env/step_result.h"
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
  // 0 - reverse: no reverse speed is 0, not -0 (which prints as "-0." in the spec).
  a.low = {static_cast<float>(0.0 - reverse), static_cast<float>(-w)};
  a.high = {static_cast<float>(v), static_cast<float>(w)};
  a.names = twistActionNames();
  return a;
}

void checkActions(const ActionLayout& layout, int num_envs, const float* actions,
                  std::size_t count) {
  const std::size_t a = layout.low.size();
  const std::size_t expected = static_cast<std::size_t>(num_envs) * a;
  if (actions == nullptr || count != expected) {
    std::ostringstream s;
    s << "actions: expected " << expected << " values (" << num_envs << " envs x " << a
      << " dofs), got " << (actions == nullptr ? 0 : count);
    throw InputError(s.str());
  }
  for (std::size_t i = 0; i < expected; ++i) {
    if (!std::isfinite(actions[i])) {
      std::ostringstream s;
      s << "actions[env " << i / a << ", " << layout.names[i % a] << "] = " << actions[i]
        << " is not finite";
      throw InputError(s.str());
    }
  }
}

void actionsToTargets(const ActionLayout& layout, int num_envs, std::size_t dofs,
                      const float* actions, bool raw, float* clamped, float* targets,
                      const float* speed_caps) {
  const std::size_t a = layout.low.size();
  const std::size_t count = static_cast<std::size_t>(num_envs) * a;
  for (std::size_t i = 0; i < count; ++i) {
    clamped[i] = std::clamp(actions[i], layout.low[i % a], layout.high[i % a]);
  }
  if (layout.drive) {
    for (int e = 0; e < num_envs; ++e) {
      if (speed_caps) clamped[2 * e] = std::min(clamped[2 * e], speed_caps[e]);
      const std::array<double, 2> wheels =
          layout.drive->wheelTargets({clamped[2 * e], clamped[2 * e + 1]});
      for (std::size_t d = 0; d < dofs; ++d) targets[e * dofs + d] = static_cast<float>(wheels[d]);
    }
  } else {
    std::copy(raw ? actions : clamped, (raw ? actions : clamped) + count, targets);
  }
}

}  // namespace jetbot_rl
