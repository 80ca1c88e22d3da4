#pragma once

#include <memory>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {

/// Everything that defines a batch of envs besides the robot: the batch and its physics, and the
/// task. The env node, the in-process trainer (~env_config), the evaluator and the benchmarks
/// read it from the same field list and build the env with makeEnv().
struct EnvSetup {
  EnvConfig env;    ///< num_envs, physics, randomisation, motor model, ...
  TaskConfig task;  ///< task, reward_variant
};

template <typename C, typename V>
IfConfig<C, EnvSetup> visitFields(C& c, V&& v) {
  visitFields(c.env, v);
  visitFields(c.task, v);
}

/// EnvConfig's rules between fields.
inline void checkFieldRules(const EnvSetup& setup) { checkFieldRules(setup.env); }

/// The batch `setup` describes, on `robot`. Validates `setup` (ConfigError naming the field) and
/// the dofs against the robot (ModelError naming the joint).
std::unique_ptr<BatchedEnv> makeEnv(RobotModelConstPtr robot, const EnvSetup& setup);

/// Reads the fields present in each YAML file of `paths` in turn over `setup`, the files parsed
/// as YAML (flattenYaml(): lists in either style, as rosparam loads them; later files win;
/// unknown keys are ignored, as in a parameter file that also holds a node's other parameters; a
/// relative world/map is relative to the file that gives it).
/// Throws ConfigError naming the file that cannot be read or the field with a value of the wrong
/// type. Does not validate.
void readEnvSetupFiles(const std::vector<std::string>& paths, EnvSetup& setup);

}  // namespace jetbot_rl
