#include "jetbot_rl/eval/dwa_actor.h"

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace {

const NavigationTask& navigationOf(const BatchedEnv& env) {
  const auto* task = dynamic_cast<const NavigationTask*>(&env.task());
  if (!task) {
    throw ConfigError("the DWA baseline drives the navigation task (task = " + env.task().name() +
                      ")");
  }
  if (!env.scanner()) throw ConfigError("the DWA baseline needs a laser scanner (scan/link)");
  if (!actsByTwist(env.spec())) {
    throw ConfigError("the DWA baseline commands a twist: give action_space twist");
  }
  return *task;
}

}  // namespace

DwaActor::DwaActor(const BatchedEnv& env, const DwaConfig& config)
    : task_(navigationOf(env)),
      planner_(config, env.world() ? env.world()->robotRadius() : 0.0),
      trackers_(env.numEnvs()) {
  for (int e = 0; e < env.numEnvs(); ++e) trackers_[e].reset(task_.path(e));
}

void DwaActor::episodesBegan(const std::vector<std::uint32_t>& ids) {
  for (std::uint32_t e : ids) trackers_[e].reset(task_.path(static_cast<int>(e)));
}

void DwaActor::act(const BatchedEnv& env, std::vector<float>& actions) {
  const ScannerSpec& scanner = *env.scanner();
  const double increment = scanner.angleIncrement();
  actions.assign(static_cast<std::size_t>(env.numEnvs()) * 2, 0.0f);
  DwaInput in;
  for (int e = 0; e < env.numEnvs(); ++e) {
    const EnvView view = env.view(e);
    const RootState s = view.rootState();
    setRobot(in, s.position, s.orientation, s.com_linear_velocity, s.angular_velocity);
    in.path = task_.path(e);
    trackers_[e].track(in.position);
    in.local_goal = trackers_[e].lookahead(planner_.config().local_goal_distance);
    // The scan's returns in the env frame (its beams' frame on the root body, else on its body).
    in.obstacles.clear();
    if (const float* scan = view.scan()) {
      const Eigen::Isometry3d body = scanner.body == 0
                                         ? Eigen::Translation3d(s.position) * s.orientation
                                         : view.linkPoses().at(scanner.body).pose;
      const Eigen::Isometry3d sensor = body * scanner.pose_in_body;
      for (int k = 0; k < scanner.samples; ++k) {
        if (scan[k] == kNoReturn) continue;
        const double range = finiteRange(scan[k], scanner);
        const double angle = scanner.min_angle + k * increment;
        const Eigen::Vector3d p =
            sensor * Eigen::Vector3d(range * std::cos(angle), range * std::sin(angle), 0.0);
        in.obstacles.push_back(p.head<2>());
      }
    }
    const DwaCommand command = planner_.plan(in);
    actions[2 * e] = static_cast<float>(command.speed);
    actions[2 * e + 1] = static_cast<float>(command.yaw_rate);
  }
}

}  // namespace jetbot_rl
