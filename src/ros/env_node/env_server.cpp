#include "jetbot_rl/ros/env_node/env_server.h"

#include <ros/console.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/msg_conversion.h"
#include "jetbot_rl/ros/env_node/sim_clock.h"
#include "jetbot_rl/tasks/task_capabilities.h"

namespace jetbot_rl {

EnvServer::EnvServer(BatchedEnv& env, EnvMode mode, double action_timeout)
    : env_(env), spec_(env.spec()), mode_(mode), action_timeout_(action_timeout) {
  const std::size_t action_count = static_cast<std::size_t>(env_.numEnvs()) * env_.actionDim();
  zero_targets_.assign(action_count, 0.0f);
  current_targets_.reserve(action_count);
  pending_targets_.reserve(action_count);
  mixed_targets_.reserve(action_count);
  updateState();
}

void EnvServer::updateState() {
  auto msg = boost::make_shared<EnvStep>();
  toMsg(env_.state(), spec_, simTime(env_.state().step, env_.controlDt()), *msg);
  state_ = msg;
  counters_.obstacles_left_out = env_.obstaclesGivenUp();
  counters_.layouts_unmade = env_.layoutsUnmade();
  counters_.movers_left_out = env_.moversGivenUp();
}

bool EnvServer::onWheelTargets(const WheelTargets& msg, SteadyTime received) {
  if (mode_ == EnvMode::kRealtime) {
    // Validated by the core when the next tick steps with it (see onTick).
    pending_targets_.assign(msg.velocities.begin(), msg.velocities.end());
    pending_time_ = received;
    has_pending_ = true;
    return false;
  }
  std::string reason;
  if (tryLockstep(msg, reason)) return true;
  reject("wheel_targets rejected: " + reason);
  return false;
}

bool EnvServer::onStep(const Step::Request& req, Step::Response& res) {
  bool stepped = false;
  if (mode_ == EnvMode::kRealtime) {
    res.success = false;
    res.message = "~step is only served in lockstep mode; publish on ~wheel_targets instead";
  } else {
    std::string reason;
    stepped = tryLockstep(req.actions, reason);
    res.success = stepped;
    if (!stepped) {
      reject("step rejected: " + reason);
      res.message = reason;
    }
  }
  res.state = *state_;
  return stepped;
}

bool EnvServer::onReset(const Reset::Request& req, Reset::Response& res) {
  std::optional<std::uint64_t> seed;
  if (req.seed >= 0) seed = static_cast<std::uint64_t>(req.seed);
  try {
    env_.reset(req.env_ids, seed, req.episode_steps);
  } catch (const InputError& e) {
    ROS_WARN_THROTTLE(1.0, "reset rejected: %s", e.what());
    res.success = false;
    res.message = e.what();
    res.state = *state_;
    return false;
  }
  updateState();
  res.success = true;
  res.message = "reset " +
                (req.env_ids.empty() ? std::string("all") : std::to_string(req.env_ids.size())) +
                " envs" + (seed ? " with seed " + std::to_string(*seed) : std::string());
  res.state = *state_;
  return true;
}

void EnvServer::onSetCommand(const SetCommand::Request& req, SetCommand::Response& res) {
  Task& task = env_.task();
  Commandable* commandable = capability<Commandable>(task);
  if (!commandable) {
    res.success = false;
    res.message = "task '" + task.name() +
                  "' has no command: start the env with a task that takes one (parameter task)";
    return;
  }
  try {
    commandable->setCommand(static_cast<int>(req.env_id), {req.x, req.y}, req.hold);
  } catch (const InputError& e) {
    res.success = false;
    res.message = e.what();
    return;
  }
  res.success = true;
  res.message = "command of env " + std::to_string(req.env_id) + " set" +
                (req.hold ? ", held across resets" : "") + "; observed from the next step";
}

void EnvServer::onTick(SteadyTime now) {
  if (has_pending_) {
    has_pending_ = false;
    // A message older than the time-out would only brake: it is dropped unapplied.
    if (now - pending_time_ <= action_timeout_) {
      try {
        stepMixed(pending_targets_, now);
        current_targets_.swap(pending_targets_);
        current_time_ = pending_time_;
        has_current_ = true;
        return;
      } catch (const InputError& e) {
        reject(std::string("wheel_targets rejected: ") + e.what());
      }
    }
  }
  if (has_current_ && now - current_time_ <= action_timeout_) {
    stepMixed(current_targets_, now);
  } else {
    stepMixed(zero_targets_, now);  // no fresh targets: brake
  }
}

void EnvServer::stepMixed(const std::vector<float>& targets, SteadyTime now) {
  if (!cmd_vel_ || !cmd_vel_->anyFresh(now)) {
    stepWith(targets.data(), targets.size());
    return;
  }
  // A WheelTargets message is valid or not as a whole, even where cmd_vel overrides it: an
  // invalid one goes to the core unmixed, which rejects it with its reason and steps nothing.
  const bool valid =
      targets.size() == zero_targets_.size() &&
      std::all_of(targets.begin(), targets.end(), [](float v) { return std::isfinite(v); });
  if (!valid) {
    stepWith(targets.data(), targets.size());
    return;
  }
  mixed_targets_.assign(targets.begin(), targets.end());
  cmd_vel_->apply(now, mixed_targets_.data(), mixed_targets_.size());
  stepWith(mixed_targets_.data(), mixed_targets_.size());
}

void EnvServer::enableCmdVel(const DiffDrive& drive, int envs, double timeout) {
  if (env_.actionDim() != 2) {
    throw ConfigError("cmd_vel needs a differential drive of 2 dofs, the env has " +
                      std::to_string(env_.actionDim()));
  }
  cmd_vel_ = std::make_unique<CmdVelMixer>(drive, std::min(envs, env_.numEnvs()), timeout,
                                           env_.config().action_space == ActionSpace::kTwist);
}

bool EnvServer::onCmdVel(int env, const geometry_msgs::Twist& msg, SteadyTime received) {
  const std::string topic = "cmd_vel of env " + std::to_string(env);
  if (mode_ == EnvMode::kLockstep) {
    rejectCmdVel(topic +
                 " rejected: lockstep mode steps only with WheelTargets (training); "
                 "mode realtime drives by cmd_vel");
    return false;
  }
  if (!cmd_vel_) {
    rejectCmdVel(topic + " rejected: no robot envs (robot_view_envs 0)");
    return false;
  }
  try {
    cmd_vel_->set(env, msg, received);
  } catch (const InputError& e) {
    rejectCmdVel(topic + " rejected: " + e.what());
    return false;
  }
  return true;
}

void EnvServer::rejectCmdVel(const std::string& reason) {
  ++counters_.cmd_vel_rejections;
  counters_.last_cmd_vel_rejection = reason;
  ROS_WARN_THROTTLE(1.0, "%s (%llu cmd_vel rejected so far)", reason.c_str(),
                    static_cast<unsigned long long>(counters_.cmd_vel_rejections));
}

bool EnvServer::tryLockstep(const WheelTargets& targets, std::string& reason) {
  const std::uint64_t current = env_.state().step;
  if (targets.step != current) {
    reason = std::string(targets.step < current ? "stale" : "future") + " step " +
             std::to_string(targets.step) + ": the current step is " + std::to_string(current);
    return false;
  }
  try {
    stepWith(targets.velocities.data(), targets.velocities.size());
  } catch (const InputError& e) {
    reason = e.what();
    return false;
  }
  return true;
}

void EnvServer::stepWith(const float* targets, std::size_t count) {
  const StepResult& result = env_.step(targets, count);  // throws before changing anything
  ++counters_.steps;
  if (!result.divergences.empty()) {
    counters_.diverged = env_.divergedCount();
    counters_.last_divergence = result.divergences.back().reason;
    ROS_WARN_THROTTLE(1.0, "step %llu: %zu env(s) diverged and were reset; last: %s",
                      static_cast<unsigned long long>(result.step), result.divergences.size(),
                      result.divergences.back().reason.c_str());
  }
  updateState();
}

void EnvServer::countMalformed(const std::string& reason) {
  ++counters_.malformed;
  counters_.last_malformed = reason;
  ++counters_.rejections;
  counters_.last_rejection = reason;
  ROS_WARN_THROTTLE(1.0, "%s (%llu malformed so far)", reason.c_str(),
                    static_cast<unsigned long long>(counters_.malformed));
}

void EnvServer::reject(const std::string& reason) {
  ++counters_.rejections;
  counters_.last_rejection = reason;
  ROS_WARN_THROTTLE(1.0, "%s (%llu rejected so far)", reason.c_str(),
                    static_cast<unsigned long long>(counters_.rejections));
}

}  // namespace jetbot_rl
