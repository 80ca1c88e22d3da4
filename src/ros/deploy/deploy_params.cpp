#include "jetbot_rl/ros/deploy/deploy_params.h"

namespace jetbot_rl {

void checkFieldRules(const DeployParams& params) {
  const DriverParams& p = params.driver;
  if (p.checkpoint.empty()) {
    throwInvalid("checkpoint", "''", "name a checkpoint file or a run directory");
  }
  if (p.dof_names.size() != 2) {
    throwInvalid("dof_names", listText(p.dof_names), "must name the two wheel joints");
  }
  if (!p.scan_angles.empty() &&
      (p.scan_angles.size() != 2 || p.scan_angles[0] > p.scan_angles[1])) {
    throwInvalid("scan_angles", listText(p.scan_angles),
                 "must be empty (the checkpoint's) or [first, last], first <= last");
  }
  if (!p.scan_range.empty() && (p.scan_range.size() != 2 || !(p.scan_range[0] < p.scan_range[1]))) {
    throwInvalid("scan_range", listText(p.scan_range),
                 "must be empty (the checkpoint's) or [min, max], min < max");
  }
}

}  // namespace jetbot_rl
