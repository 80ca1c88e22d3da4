#include "jetbot_rl/ros/deploy/deploy_params.h"

#include <cmath>
#include <sstream>

#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {

void checkFieldRules(const DeployParams& params) {
  const DriverParams& p = params.driver;
  if (p.checkpoint.empty()) {
    throwInvalid("checkpoint", "''", "name a checkpoint file or a run directory");
  }
  if (p.dof_names.size() != 2) {
    throwInvalid("dof_names", listText(p.dof_names), "must name the two wheel joints");
  }
  checkFieldRules(params.local.dwa);
}

std::vector<std::string> takeTrainedSettings(DeployParams& params, const ObserverSpec& trained) {
  std::vector<std::string> overrides;
  // `unset`: the parameter's "take the checkpoint's" value.
  const auto take = [&overrides](const char* param, double& value, bool unset, const char* field,
                                 double checkpoints) {
    if (unset) {
      value = checkpoints;
    } else if (std::abs(value - checkpoints) > 1e-9) {
      std::ostringstream s;
      s << param << " = " << value << " overrides the checkpoint's " << field << " = "
        << checkpoints;
      overrides.push_back(s.str());
    }
  };
  DriverParams& d = params.driver;
  GoalPursuitParams& g = params.pursuit;
  if (trained.wheel_radius > 0.0 && trained.wheel_separation > 0.0) {
    take("wheel_radius", d.wheel_radius, d.wheel_radius == 0.0, "wheel_radius",
         trained.wheel_radius);
    take("wheel_separation", d.wheel_separation, d.wheel_separation == 0.0, "wheel_separation",
         trained.wheel_separation);
  }
  if (trained.goal_radius > 0.0) {
    take("xy_goal_tolerance", g.xy_goal_tolerance, g.xy_goal_tolerance == 0.0, "goal_radius",
         trained.goal_radius);
  }
  take("footprint_radius", g.footprint_radius, g.footprint_radius == 0.0, "footprint_radius",
       trained.footprint_radius);
  if (trained.path_lookahead > 0.0) {
    take("path_clearance", g.path_clearance, g.path_clearance < 0.0, "path_clearance",
         trained.path_clearance);
    take("path_clearance_cost", g.path_clearance_cost, g.path_clearance_cost < 0.0,
         "path_clearance_cost", trained.path_clearance_cost);
  } else {  // trained without a path: a carrot's path (with a map) plans as the task would
    const NavigationConfig task_defaults;
    if (g.path_clearance < 0.0) g.path_clearance = task_defaults.path_clearance;
    if (g.path_clearance_cost < 0.0) g.path_clearance_cost = task_defaults.path_clearance_cost;
  }
  return overrides;
}

}  // namespace jetbot_rl
