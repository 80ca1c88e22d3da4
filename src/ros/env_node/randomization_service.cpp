#include "jetbot_rl/ros/env_node/randomization_service.h"

#include <string>
#include <vector>

#include "jetbot_rl/ros/common/bounded_service.h"
#include "jetbot_rl/ros/env_node/sim_clock.h"

namespace jetbot_rl {

void answerGetRandomization(const BatchedEnv& env, const GetRandomization::Request& req,
                            GetRandomization::Response& res) {
  const int n = env.numEnvs();
  std::vector<std::uint32_t> ids = req.env_ids;
  if (ids.empty()) {
    for (int e = 0; e < n; ++e) ids.push_back(static_cast<std::uint32_t>(e));
  }
  std::vector<bool> seen(n, false);
  for (std::uint32_t id : ids) {
    if (id >= static_cast<std::uint32_t>(n) || seen[id]) {
      res.success = false;
      res.message =
          "env_ids: id " + std::to_string(id) +
          (id >= static_cast<std::uint32_t>(n) ? " is out of range [0, " + std::to_string(n) + ")"
                                               : " is listed twice");
      return;
    }
    seen[id] = true;
  }
  EnvRandomization& msg = res.randomization;
  msg.header.stamp = simTime(env.state().step, env.controlDt());
  msg.step = env.state().step;
  msg.env_ids = ids;
  msg.num_dofs = 0;
  for (std::uint32_t id : ids) {
    const RandomizationDraw r = env.view(static_cast<int>(id)).randomization();
    msg.mass_scale.push_back(r.mass_scale);
    msg.wheel_friction.push_back(r.wheel_friction);
    msg.drive_gain_scale.push_back(r.drive_gain_scale);
    msg.effort_limit_scale.push_back(r.effort_limit_scale);
    msg.wheel_radius_scale.push_back(r.wheel_radius_scale);
    msg.initial_yaw.push_back(r.initial_yaw);
    msg.initial_speed.push_back(r.initial_speed);
    msg.action_delay_steps.push_back(static_cast<std::uint32_t>(r.action_delay_steps));
    msg.num_dofs = static_cast<std::uint32_t>(r.motor_trim.size());
    msg.motor_dead_zone.insert(msg.motor_dead_zone.end(), r.motor_dead_zone.begin(),
                               r.motor_dead_zone.end());
    msg.motor_trim.insert(msg.motor_trim.end(), r.motor_trim.begin(), r.motor_trim.end());
  }
  res.success = true;
}

ros::ServiceServer advertiseGetRandomization(ros::NodeHandle& pnh, const BatchedEnv& env,
                                             std::mutex& state_mutex, RefusalHandler on_refusal) {
  return advertiseServiceBounded<GetRandomization>(
      pnh, "get_randomization",
      [&env, &state_mutex](GetRandomization::Request& req, GetRandomization::Response& res) {
        std::lock_guard<std::mutex> lock(state_mutex);
        answerGetRandomization(env, req, res);
        return true;
      },
      std::move(on_refusal));
}

}  // namespace jetbot_rl
