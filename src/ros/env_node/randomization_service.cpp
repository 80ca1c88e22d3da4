#include "jetbot_rl/ros/env_node/randomization_service.h"

#include <string>
#include <vector>

#include "jetbot_rl/ros/common/bounded_service.h"
#include "jetbot_rl/ros/common/msg_fields.h"
#include "jetbot_rl/ros/env_node/sim_clock.h"

namespace jetbot_rl {

void appendDraw(const RandomizationDraw& draw, EnvRandomization& msg) {
  // Field by field, by name: the draw's field list and the message's per-env arrays.
  visitFields(draw, [&msg](const char* name, const auto& value, const auto&, const char*) {
    bool found = false;
    visitMsgFields(msg, [&](const std::string& field, auto& to) {
      if (field != name) return;
      appendField(field, to, value);
      found = true;
    });
    if (!found) {
      throw Error(std::string("EnvRandomization.msg has no field ") + name +
                  " (RandomizationDraw has)");
    }
  });
}

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
    appendDraw(r, msg);
    msg.num_dofs = static_cast<std::uint32_t>(r.motor_trim.size());
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
