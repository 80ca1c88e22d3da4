#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace jetbot_rl {

/// An env that was reset on its own because its physics diverged.
struct Divergence {
  std::uint32_t env = 0;
  std::string reason;
};

/// The batch after a step or a reset: what the core returns and what every learner sees
/// (in-process or through the EnvStep message, whose fields it mirrors).
struct StepResult {
  std::uint64_t step = 0;                    ///< Control steps applied; resets do not count.
  std::vector<float> observations;           ///< num_envs x obs_dim, after auto-reset.
  std::vector<float> rewards;                ///< num_envs (0 after a reset()).
  std::vector<std::uint8_t> terminated;      ///< num_envs.
  std::vector<std::uint8_t> truncated;       ///< num_envs: time-out or divergence.
  std::vector<std::uint32_t> episode_steps;  ///< num_envs: steps into the current episode.
  std::vector<std::uint32_t> reset_env_ids;  ///< Envs that ended in this step and were reset.
  std::vector<float> final_observations;     ///< len(reset_env_ids) x obs_dim, before the reset.
  /// len(reset_env_ids): how each ended episode ended (Outcome: 0 time-out, 1 success, 2 failure).
  std::vector<std::uint8_t> outcomes;
  std::vector<Divergence> divergences;  ///< Envs among reset_env_ids that diverged.
};

/// What a learner needs to know about a batch (the content of the EnvSpec message).
struct BatchSpec {
  int num_envs = 0;
  int obs_dim = 0;
  int action_dim = 0;
  std::vector<float> action_low, action_high;  ///< Per action dimension [rad/s for wheels].
  double control_dt = 0.0;                     ///< [s]
  int max_episode_length = 0;                  ///< [control steps]
  std::string task;
  std::vector<std::string> observation_names;  ///< One per observation component.
  std::vector<std::string> action_names;       ///< One per action component (the dof names).
  /// The scan beams the observation holds (navigation): their angles [rad, in the scanner's frame],
  /// and the scanner's [range_min, range_max] [m] they are clamped into and divided by. Empty
  /// when the task observes no scan.
  std::vector<double> scan_beam_angles, scan_range;
};

}  // namespace jetbot_rl
