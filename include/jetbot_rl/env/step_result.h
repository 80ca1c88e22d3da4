#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"

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

/// What a learner needs to know about a batch (the content of the EnvSpec message). One schema
/// (its visitFields below) drives the message conversion, the checkpoint's and meta.yaml's copy,
/// the agreement checks (env nodes of one batch, a checkpoint and an env) and the docs; the
/// Python client reads the fields from the message: a new field is added here, in its field
/// list, in EnvSpec.msg and where it is used.
struct BatchSpec {
  int num_envs = 0;
  int obs_dim = 0;
  int action_dim = 0;
  std::vector<float> action_low, action_high;  ///< Per action dimension [rad/s for wheels].
  double control_dt = 0.0;                     ///< [s]
  int max_episode_length = 0;                  ///< [control steps]
  std::string task;
  std::vector<std::string> observation_names;  ///< One per observation component.
  /// Per observation component, the range it stays in (±inf where none is known).
  std::vector<float> observation_low, observation_high;
  std::vector<std::string> action_names;  ///< One per action component (the dof names).
  /// The task has goals: its episodes end in success or collision as well as time-outs.
  bool has_goals = false;
  /// The robot's cmd_vel kinematics (DiffDrive); 0 when it is no differential drive [m].
  double wheel_radius = 0.0, wheel_separation = 0.0;
  /// The scan beams the observation holds (navigation): their angles [rad, in the scanner's frame],
  /// and the scanner's [range_min, range_max] [m] they are clamped into and divided by. Empty
  /// when the task observes no scan.
  std::vector<double> scan_beam_angles, scan_range;
  /// Each beam's sector [rad]: the smallest reading in [angle, angle + width); 0: the nearest
  /// sample (and in checkpoints written before sectors).
  double scan_beam_width = 0.0;
  /// A task that observes a global path: the observed point's distance along it [m]; 0: none.
  double path_lookahead = 0.0;
};

/// The fields of BatchSpec a trained policy is bound to: an env it acts on must have the same
/// (what it observes and how it acts).
template <typename C, typename V>
IfConfig<C, BatchSpec> visitPolicyBoundFields(C& c, V&& v) {
  v("task", c.task, AnyValue{}, "The RL task.");
  v("obs_dim", c.obs_dim, AnyValue{}, "Observation components per env.");
  v("action_dim", c.action_dim, AnyValue{}, "Action components per env.");
  v("observation_names", c.observation_names, AnyValue{}, "One per observation component.");
  v("action_names", c.action_names, AnyValue{},
    "One per action component: the dof names, or linear_x, angular_z (a twist).");
  v("scan_beam_angles", c.scan_beam_angles, AnyValue{"rad"},
    "The scan beams the observation holds, in the scanner's frame (empty: no scan observed).");
  v("scan_range", c.scan_range, AnyValue{"m"},
    "The scanner's [range_min, range_max] the beams are clamped into and divided by the max of.");
  v("scan_beam_width", c.scan_beam_width, AnyValue{"rad"},
    "Each beam's sector: the beam is the smallest reading in [angle, angle + width); 0: the "
    "sample nearest to its angle.");
  v("path_lookahead", c.path_lookahead, AnyValue{"m"},
    "A task that observes a global path (nav/path): the observed point's distance along it past "
    "the robot (nav/path_lookahead); 0: no path observed.");
}

/// Every field of BatchSpec (EnvSpec.msg names the same).
template <typename C, typename V>
IfConfig<C, BatchSpec> visitFields(C& c, V&& v) {
  v("num_envs", c.num_envs, AnyValue{}, "Envs in the batch.");
  visitPolicyBoundFields(c, v);
  v("action_low", c.action_low, AnyValue{},
    "Lower action bounds, per component [rad/s for wheels; m/s, rad/s for a twist].");
  v("action_high", c.action_high, AnyValue{}, "Upper action bounds, per component.");
  v("control_dt", c.control_dt, AnyValue{"s"}, "Control step.");
  v("max_episode_length", c.max_episode_length, AnyValue{"control steps"},
    "Episodes are truncated at step max_episode_length - 1.");
  v("observation_low", c.observation_low, AnyValue{},
    "Per observation component, the lowest value it takes (-inf where none is known).");
  v("observation_high", c.observation_high, AnyValue{},
    "Per observation component, the highest value it takes (inf where none is known).");
  v("has_goals", c.has_goals, AnyValue{},
    "The task has goals: its episodes end in success (OUTCOME_SUCCESS) or collision as well as "
    "time-outs.");
  v("wheel_radius", c.wheel_radius, AnyValue{"m"},
    "The cmd_vel kinematics' wheel radius; 0: the robot is no differential drive.");
  v("wheel_separation", c.wheel_separation, AnyValue{"m"},
    "The cmd_vel kinematics' wheel separation; 0: the robot is no differential drive.");
}

/// The action names of action_space twist (v [m/s], omega [rad/s]).
inline const std::vector<std::string>& twistActionNames() {
  static const std::vector<std::string> names{"linear_x", "angular_z"};
  return names;
}
/// True when `spec`'s actions are a twist (action_space twist), not wheel targets.
inline bool actsByTwist(const BatchSpec& spec) { return spec.action_names == twistActionNames(); }

/// Sizes that fit: num_envs, obs_dim and action_dim >= 1, as many names and bounds as
/// components, max_episode_length >= 2, control_dt > 0, scan_range two values with the beams;
/// ConfigError naming the field and its value.
void checkFieldRules(const BatchSpec& spec);

/// One line "FIELD: THEIRS differs from MINE" per field of `theirs` that differs from `mine`,
/// over every field but num_envs, or only the policy-bound ones; a field `mine` does not hold (at
/// its default: written before the field existed) is not compared when `skip_unset`.
std::vector<std::string> specDifferences(const BatchSpec& mine, const BatchSpec& theirs,
                                         bool policy_bound_only, bool skip_unset);

}  // namespace jetbot_rl
