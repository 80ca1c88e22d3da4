#pragma once

#include <ros/node_handle.h>

#include <limits>
#include <optional>
#include <string>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/ros/client/connect_envs.h"
#include "jetbot_rl/ros/common/env_mode.h"

namespace jetbot_rl {
namespace ppo {

/// Private parameters of jetbot_policy_node (a policy driving env nodes; a robot:
/// jetbot_deploy_node).
struct PolicyParams {
  std::string checkpoint;    ///< Checkpoint file, or a run directory (its checkpoints/best.pt).
  EnvNodesParams env_nodes;  ///< The env nodes to drive as one batch, step_timeout.
  EnvMode mode = EnvMode::kRealtime;  ///< The env's mode.
  int steps = 0;                      ///< Control steps to drive; 0: until Ctrl-C.
  int reset_seed = -1;                ///< Seed of the initial reset; < 0 keeps the env's stream.
};

template <typename C, typename V>
IfConfig<C, PolicyParams> visitFields(C& c, V&& v) {
  v("checkpoint", c.checkpoint, AnyValue{"", "required"},
    "Checkpoint file, or a run directory (its checkpoints/best.pt).");
  visitFields(c.env_nodes, v);
  v("mode", c.mode, AnyValue{}, "The env nodes' mode: realtime or lockstep.");
  v("steps", c.steps, atLeast(0, "control steps", "0: until Ctrl-C"), "Control steps to drive.");
  v("reset_seed", c.reset_seed, atLeast(std::numeric_limits<int>::min(), "", "< 0: no reseed"),
    "Seed of the initial reset.");
}

/// checkpoint must be given.
void checkFieldRules(const PolicyParams& params);

/// Reads, validates and echoes the policy node's private parameters under `pnh` (loadParams), a
/// run directory resolved to its checkpoints/best.pt. std::nullopt after ROS_FATAL naming a bad
/// one.
std::optional<PolicyParams> loadPolicyParams(const ros::NodeHandle& pnh);

}  // namespace ppo
}  // namespace jetbot_rl
