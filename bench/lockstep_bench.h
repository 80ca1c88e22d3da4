#pragma once

#include <ros/node_handle.h>

#include <string>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/ros/common/param_reader.h"

namespace jetbot_rl {

/// What the lockstep benchmark measures, and against which env node: LockstepBenchNodelet's
/// private parameters, jetbot_rl_ros_bench's --env-node, --num-envs and --steps.
struct LockstepBenchParams {
  std::string env_node = "jetbot_env";  ///< The env node (relative: in the caller's namespace).
  int num_envs = 1024;                  ///< Its num_envs (checked against its ~spec).
  int steps = 1000;                     ///< Timed round trips.
};

template <typename C, typename V>
IfConfig<C, LockstepBenchParams> visitFields(C& c, V&& v) {
  v("env_node", c.env_node, GraphName{},
    "The env node to step (relative: in the nodelet's namespace).");
  v("num_envs", c.num_envs, inRange(1, 1000000), "Its num_envs (checked against its ~spec).");
  v("steps", c.steps, inRange(1, 1000000000, "round trips"), "Timed round trips per path.");
}

/// How jetbot_rl_ros_bench and LockstepBenchNodelet run the benchmark.
struct LockstepBenchOptions {
  LockstepBenchParams params;
  bool compare_core = true;  ///< Also step the core in-process with the node's parameters.
  /// Answer each EnvStep in the thread that receives it (roscpp's network thread: no hand-off)
  /// instead of in the bench's own thread. In one process with the env (nodelets) it must be
  /// false: an answer published from inside the env's publish would re-enter roscpp's
  /// publication of our own targets, which roscpp does not allow.
  bool answer_inline = true;
};

/**
 * The end-to-end lockstep benchmark: answers each EnvStep at once with random WheelTargets for
 * the same step, records every round trip (publish -> matching EnvStep) and prints percentiles,
 * then (optionally) the core's figure for the same parameters, and as its last line
 * `env_steps_per_s=<number>`. Returns the process exit code.
 */
int runLockstepBench(ros::NodeHandle& nh, const LockstepBenchOptions& options);

}  // namespace jetbot_rl
