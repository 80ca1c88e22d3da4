#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/tasks/observer_spec.h"

namespace jetbot_rl {

class TaskObserver;

/// An env that was reset on its own because its physics diverged.
struct Divergence {
  std::uint32_t env = 0;
  std::string reason;
};

/// Every env's latest camera images after a step or a reset (docs/camera.md), each row-major from
/// its top left pixel; an image the camera does not make is empty (without a camera, all are).
struct BatchImages {
  int width = 0, height = 0;        ///< [px]
  std::vector<std::uint8_t> rgb;    ///< num_envs x height x width x 3 (rgb8).
  std::vector<float> depth;         ///< num_envs x height x width [m] (32FC1, REP 118).
  std::vector<std::uint8_t> label;  ///< num_envs x height x width (SurfaceClass values).
  std::vector<std::uint8_t> fresh;  ///< num_envs: 1 where the images were made in the last call.
};

/// Empties `images`' buffers (keeps their size in pixels).
inline void clearImages(BatchImages& images) {
  images.rgb.clear();
  images.depth.clear();
  images.label.clear();
  images.fresh.clear();
}

/// The batch after a step or a reset: what the core returns and what every learner sees
/// (in-process or through the EnvStep message, whose fields it mirrors; images in-process only).
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
  /// The camera's images, after auto-reset as the observations.
  BatchImages images;
  /// len(reset_env_ids) envs' last images of their ended episodes (in reset_env_ids order; no
  /// `fresh`): what SB3 keeps as an image policy's terminal_observation.
  BatchImages final_images;
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
  /// The observation contract: the scan, goal and path settings and the robot's geometry the
  /// observation depends on (makeObserver() builds the observer from this spec).
  ObserverSpec observer;
  /// The camera images every step carries (StepResult::images, EnvStep images_*): a subset of
  /// rgb, depth, label in that order; empty: none (no camera, or camera/batch_images false).
  std::vector<std::string> image_kinds;
  int image_width = 0;   ///< [px]; 0 without image_kinds.
  int image_height = 0;  ///< [px]; 0 without image_kinds.
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
  visitObservationFields(c.observer, v);
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
  visitGoalAndRobotFields(c.observer, v);
  v("image_kinds", c.image_kinds, AnyValue{},
    "The camera images each step carries, of rgb (rgb8), depth (32FC1 [m]), label (mono8), in "
    "that order; [] when none.");
  v("image_width", c.image_width, AnyValue{"px"}, "Their width; 0 without images.");
  v("image_height", c.image_height, AnyValue{"px"}, "Their height; 0 without images.");
}

/// True when `spec`'s steps carry images of `kind` (rgb, depth or label).
inline bool carriesImage(const BatchSpec& spec, const std::string& kind) {
  for (const std::string& k : spec.image_kinds) {
    if (k == kind) return true;
  }
  return false;
}

/// The action names of action_space twist (v [m/s], omega [rad/s]).
inline const std::vector<std::string>& twistActionNames() {
  static const std::vector<std::string> names{"linear_x", "angular_z"};
  return names;
}
/// True when `spec`'s actions are a twist (action_space twist), not wheel targets.
inline bool actsByTwist(const BatchSpec& spec) { return spec.action_names == twistActionNames(); }
/// The top speed of the robot a policy of `spec` drives: a twist's linear_x bound, else the
/// slowest wheel's velocity bound times the wheel radius (the observer's kinematics); 0 when
/// neither is known [m/s].
double topSpeed(const BatchSpec& spec);

/// Sizes that fit: num_envs, obs_dim and action_dim >= 1, as many names and bounds as
/// components, max_episode_length >= 2, control_dt > 0, image kinds among rgb, depth, label in
/// that order with a size in [1, 4096] px (0 without), the observer's rules (observer_spec.h);
/// ConfigError naming the field and its value.
void checkFieldRules(const BatchSpec& spec);

/// The observer of the policy trained on `spec` (its task, action size and observation
/// contract): what a robot elsewhere observes with. ConfigError naming what the contract lacks.
std::unique_ptr<TaskObserver> makeObserver(const BatchSpec& spec);

/// One line "FIELD: THEIRS differs from MINE" per field of `theirs` that differs from `mine`,
/// over every field but num_envs, or only the policy-bound ones; a field `mine` does not hold (at
/// its default: written before the field existed) is not compared when `skip_unset`.
std::vector<std::string> specDifferences(const BatchSpec& mine, const BatchSpec& theirs,
                                         bool policy_bound_only, bool skip_unset);

}  // namespace jetbot_rl
