#include "env/env_randomizer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/robot/motor_model.h"

namespace jetbot_rl {
namespace {

/// Uniform in [range[0], range[1]]; exactly range[0] when they are equal.
double drawIn(const double* range, Rng& rng) {
  return range[0] + (range[1] - range[0]) * rng.uniform();
}
double drawIn(const std::vector<double>& range, Rng& rng) { return drawIn(range.data(), rng); }

/// A motor range list has one [min, max] for all dofs or one per dof: ConfigError otherwise.
void checkPerDof(const char* field, const std::vector<double>& ranges, int num_dofs) {
  if (ranges.size() == 2 || static_cast<int>(ranges.size()) == 2 * num_dofs) return;
  throwInvalid(field, listText(ranges),
               "must hold one [min, max] for every dof or one per dof (" +
                   std::to_string(num_dofs) + " dofs: " + std::to_string(2 * num_dofs) +
                   " values)");
}

/// Uniform integer in [range[0], range[1]].
int drawIn(const std::vector<int>& range, Rng& rng) {
  const int span = range[1] - range[0] + 1;
  return range[0] + std::min(span - 1, static_cast<int>(rng.uniform() * span));
}

/// RandomizationConfig's range named `name` (a draw field's name); Error for a field without one
/// (the two field lists disagree).
template <typename T>
const std::vector<T>& rangeNamed(const RandomizationConfig& config, const char* name) {
  const std::vector<T>* range = nullptr;
  visitFields(config, [&](const char* field, const auto& value, const auto&, const char*) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::vector<T>>) {
      if (std::strcmp(field, name) == 0) range = &value;
    }
  });
  if (!range) throw Error(std::string("RandomizationConfig has no range ") + name + " to draw");
  return *range;
}

}  // namespace

EnvRandomizer::EnvRandomizer(const EnvConfig& config, const PhysicsModel& model, int obs_dim)
    : num_envs_(config.numRows()),
      num_dofs_(static_cast<int>(model.dofs().size())),
      config_(config.randomization),
      motor_(config.motor),
      draws_at_reset_(config.randomization.drawsAtReset() || config.motor.drawsAtReset()),
      action_noise_std_(config.randomization.action_noise_std) {
  std::vector<double> limits;
  for (const auto& dof : model.dofs()) {
    limits.push_back(dof.velocity_limit);
    low_.push_back(static_cast<float>(-dof.velocity_limit));
    high_.push_back(static_cast<float>(dof.velocity_limit));
    motor_max_.push_back(motor_.max_wheel_speed > 0.0 ? motor_.max_wheel_speed
                                                      : dof.velocity_limit);
  }

  const auto& obs_std = config_.obs_noise_std;
  const bool obs_noise =
      std::any_of(obs_std.begin(), obs_std.end(), [](double s) { return s > 0; });
  if (obs_std.size() > 1 && static_cast<int>(obs_std.size()) != obs_dim) {
    throwInvalid("obs_noise_std", listText(obs_std),
                 "must hold one value (for every component) or " + std::to_string(obs_dim) +
                     " (one per observation component)");
  }
  if (obs_noise) {
    obs_noise_std_ = obs_std.size() == 1 ? std::vector<double>(obs_dim, obs_std[0]) : obs_std;
  }

  if (config_.initial_speed != std::vector<double>{0.0, 0.0}) {
    try {
      const DiffDrive drive = DiffDrive::fromRobot(model.robot(), config.dof_names, limits,
                                                   config.wheel_radius, config.wheel_separation);
      wheel_spin_.assign(num_dofs_, 0.0);
      for (const DriveWheel& wheel : {drive.left(), drive.right()}) {
        wheel_spin_[wheel.dof] = wheel.direction / drive.wheelRadius();
      }
    } catch (const Error& e) {
      throw ModelError(
          std::string("initial_speed needs a differential drive to spin the wheels: ") + e.what());
    }
  }

  shapes_targets_ = action_noise_std_ > 0.0 || config_.action_delay_steps[1] > 0 || motor_.enabled;
  if (draws_at_reset_) draws_.assign(num_envs_, RandomizationDraw{});
  if (motor_.enabled) {
    checkPerDof("motor_dead_zone", motor_.dead_zone, num_dofs_);
    checkPerDof("motor_trim", motor_.trim, num_dofs_);
    dead_zone_.assign(static_cast<std::size_t>(num_envs_) * num_dofs_, 0.0);
    trim_.assign(static_cast<std::size_t>(num_envs_) * num_dofs_, 1.0);
  }
  if (action_noise_std_ > 0.0 || obs_noise) {
    noise_.reserve(num_envs_);
    for (int e = 0; e < num_envs_; ++e) noise_.emplace_back(config.seed, e + kNoiseStream);
  }
  delay_capacity_ = config_.action_delay_steps[1];
  if (delay_capacity_ > 0) {
    delay_line_.assign(static_cast<std::size_t>(num_envs_) * delay_capacity_ * num_dofs_, 0.0f);
    delay_pos_.assign(num_envs_, 0);
  }
}

void EnvRandomizer::reseed(int env, std::uint64_t seed) {
  if (!noise_.empty()) noise_[env] = Rng(seed, env + kNoiseStream);
}

// The order of the draws is documented in docs/core.md, "Domain randomisation": changing it changes
// every randomised trajectory.
void EnvRandomizer::resetEnv(int env, Rng& rng, EnvPhysics& world) {
  RandomizationDraw& p = draws_[env];
  // Each scalar of the draw's field list from the configured range of its name, in that order.
  visitFields(p, [&](const char* name, auto& value, const auto&, const char*) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_arithmetic_v<T>) value = drawIn(rangeNamed<T>(config_, name), rng);
  });
  if (motor_.enabled) {
    for (int k = 0; k < num_dofs_; ++k) {
      const std::size_t i = static_cast<std::size_t>(env) * num_dofs_ + k;
      dead_zone_[i] = drawIn(MotorModelConfig::rangeOf(motor_.dead_zone, k), rng);
      trim_[i] = drawIn(MotorModelConfig::rangeOf(motor_.trim, k), rng);
    }
  }
  world.randomize(p, wheel_spin_);

  if (delay_capacity_ > 0) {
    // Until the first target gets through, the wheels keep the speed they start with.
    float* line = &delay_line_[static_cast<std::size_t>(env) * delay_capacity_ * num_dofs_];
    for (int slot = 0; slot < delay_capacity_; ++slot) {
      for (int k = 0; k < num_dofs_; ++k) {
        const double spin =
            wheel_spin_.empty() ? 0.0 : wheel_spin_[k] * p.initial_speed / p.wheel_radius_scale;
        line[slot * num_dofs_ + k] = std::clamp(static_cast<float>(spin), low_[k], high_[k]);
      }
    }
    delay_pos_[env] = 0;
  }
}

void EnvRandomizer::shapeTargets(int env, float* t) {
  if (action_noise_std_ > 0.0) {
    Rng& rng = noise_[env];
    for (int k = 0; k < num_dofs_; ++k) {
      t[k] = std::clamp(static_cast<float>(t[k] + action_noise_std_ * rng.gaussian()), low_[k],
                        high_[k]);
    }
  }
  const int delay = draws_.empty() ? 0 : draws_[env].action_delay_steps;
  if (delay > 0) {
    // Slot (s mod capacity) holds the target of episode step s: read step s - delay's, then
    // write this one (the same slot when delay == capacity).
    int& pos = delay_pos_[env];
    float* line = &delay_line_[static_cast<std::size_t>(env) * delay_capacity_ * num_dofs_];
    const int read = (pos - delay + delay_capacity_) % delay_capacity_;
    for (int k = 0; k < num_dofs_; ++k) {
      const float now = t[k];
      t[k] = line[read * num_dofs_ + k];
      line[pos * num_dofs_ + k] = now;
    }
    pos = (pos + 1) % delay_capacity_;
  }
  if (motor_.enabled) {
    const std::size_t row = static_cast<std::size_t>(env) * num_dofs_;
    for (int k = 0; k < num_dofs_; ++k) {
      const double v =
          motorVelocityTarget(t[k], motor_max_[k], dead_zone_[row + k], trim_[row + k]);
      t[k] = std::clamp(static_cast<float>(v), low_[k], high_[k]);
    }
  }
}

void EnvRandomizer::noiseObservation(int env, float* obs) {
  Rng& rng = noise_[env];
  for (std::size_t i = 0; i < obs_noise_std_.size(); ++i) {
    const double z = rng.gaussian();  // drawn for every component: a fixed count per observation
    if (obs_noise_std_[i] > 0.0) obs[i] = static_cast<float>(obs[i] + obs_noise_std_[i] * z);
  }
}

RandomizationDraw EnvRandomizer::values(int env) const {
  RandomizationDraw r;
  if (!draws_.empty()) {
    r = draws_[env];
  } else {
    r.wheel_friction = PhysicsModel::kWheelFriction;
  }
  if (motor_.enabled) {
    const auto row = dead_zone_.begin() + static_cast<std::ptrdiff_t>(env) * num_dofs_;
    r.motor_dead_zone.assign(row, row + num_dofs_);
    const auto trim_row = trim_.begin() + static_cast<std::ptrdiff_t>(env) * num_dofs_;
    r.motor_trim.assign(trim_row, trim_row + num_dofs_);
  }
  return r;
}

}  // namespace jetbot_rl
