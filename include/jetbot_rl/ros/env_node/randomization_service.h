#pragma once

#include <ros/node_handle.h>
#include <ros/service_server.h>

#include <mutex>

#include "jetbot_rl/GetRandomization.h"
#include "jetbot_rl/env/batched_env.h"
#include "jetbot_rl/ros/common/bounded_subscription.h"

namespace jetbot_rl {

/// Answers a ~get_randomization request from `env`: the values each listed env (all when none
/// are listed) drew at its last reset, stamped with the simulation time of the current state. An
/// unknown or repeated id: success false with the reason, and no values.
/// Appends one env's draw to `msg`'s per-env arrays, each field to the array of its name (the
/// motor values num_dofs at a time); Error naming a field the message lacks.
void appendDraw(const RandomizationDraw& draw, EnvRandomization& msg);

void answerGetRandomization(const BatchedEnv& env, const GetRandomization::Request& req,
                            GetRandomization::Response& res);

/// Advertises ~get_randomization under `pnh` (on its callback queue, requests bounded as every
/// request the node serves), answering from `env` under `state_mutex`; `on_refusal` is told of a
/// request refused unread.
ros::ServiceServer advertiseGetRandomization(ros::NodeHandle& pnh, const BatchedEnv& env,
                                             std::mutex& state_mutex, RefusalHandler on_refusal);

}  // namespace jetbot_rl
