#pragma once

#include <cstdint>
#include <vector>

#include "env/env_physics.h"
#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/env/randomization.h"
#include "jetbot_rl/rng.h"
#include "robot/physics_model.h"

namespace jetbot_rl {

/**
 * A batch's domain randomisation and motor model (docs/core.md, "Domain randomisation"): draws each
 * env's values at its resets from the env's own stream, keeps its noise stream and its delayed
 * targets, and shapes its targets and observations. Memory per env is taken only for what is on.
 * A per-env call touches only that env's slots, so threads may call it for different envs at once.
 */
class EnvRandomizer {
 public:
  /// Noise stream of env e: the stream of env id e + kNoiseStream under the batch's seed (ids are
  /// below 2^20, so it is no other env's stream).
  static constexpr std::uint64_t kNoiseStream = streams::kNoise;

  /// Throws ConfigError for an obs_noise_std of the wrong length, ModelError when initial_speed
  /// is set for a robot that is no differential drive.
  EnvRandomizer(const EnvConfig& config, const PhysicsModel& model, int obs_dim);

  /// A reset draws per-env values (resetEnv() must be called).
  bool drawsAtReset() const { return draws_at_reset_; }
  /// step() must pass the raw actions (shapeTargets() adds noise, then clamps).
  bool noisesActions() const { return action_noise_std_ > 0.0; }
  /// shapeTargets() must be called (action noise, delay or motor model).
  bool shapesTargets() const { return shapes_targets_; }
  /// noiseObservation() must be called.
  bool noisesObservations() const { return !obs_noise_std_.empty(); }

  /// Restarts env `env`'s noise stream for `seed` (with reset(env_ids, seed)).
  void reseed(int env, std::uint64_t seed);
  /// At a reset of env `env`, after EnvPhysics::reset(): draws its values from `rng` and applies
  /// them to `world`; refills its delay line with the wheel targets of its initial speed.
  void resetEnv(int env, Rng& rng, EnvPhysics& world);
  /// Turns env `env`'s targets [rad/s] (raw when noisesActions(), else clamped) into its drives'
  /// velocity targets: noise, clamping, delay, motor model.
  void shapeTargets(int env, float* targets);
  /// Adds env `env`'s observation noise to `obs` (obs_dim values).
  void noiseObservation(int env, float* obs);
  /// The values env `env` drew at its last reset.
  RandomizationDraw values(int env) const;

 private:
  int num_envs_, num_dofs_;
  RandomizationConfig config_;
  MotorModelConfig motor_;
  bool draws_at_reset_, shapes_targets_;
  std::vector<float> low_, high_;   // per dof: velocity limits [rad/s]
  std::vector<double> wheel_spin_;  // per dof [rad/m]; empty unless initial_speed is on
  std::vector<double> motor_max_;   // per dof: wheel speed at duty 1 [rad/s]
  double action_noise_std_;
  std::vector<double> obs_noise_std_;  // per component; empty: none

  std::vector<RandomizationDraw> draws_;  // per env, when drawsAtReset() (motor values aside)
  std::vector<double> dead_zone_, trim_;  // per env and dof, when the motor draws
  std::vector<Rng> noise_;                // per env, when there is noise
  int delay_capacity_ = 0;                // largest delay [control steps]
  std::vector<float> delay_line_;         // per env: capacity x dofs targets
  std::vector<int> delay_pos_;            // per env: slot of this step's target
};

}  // namespace jetbot_rl
