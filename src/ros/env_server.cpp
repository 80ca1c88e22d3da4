#include "jetbot_rl/ros/env_server.h"

#include <ros/console.h>

#include <optional>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/msg_conversion.h"
#include "jetbot_rl/ros/sim_clock.h"

namespace jetbot_rl {

EnvServer::EnvServer(BatchedEnv& env, EnvMode mode, double action_timeout)
    : env_(env), mode_(mode), action_timeout_(action_timeout) {
  const std::size_t action_count = static_cast<std::size_t>(env_.numEnvs()) * env_.actionDim();
  zero_targets_.assign(action_count, 0.0f);
  current_targets_.reserve(action_count);
  pending_targets_.reserve(action_count);
  updateState();
}

void EnvServer::updateState() {
  auto msg = boost::make_shared<EnvStep>();
  toMsg(env_.state(), env_.numEnvs(), env_.obsDim(), simTime(env_.state().step, env_.controlDt()),
        *msg);
  state_ = msg;
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
  if (task.commandDim() == 0) {
    res.success = false;
    res.message = "task '" + task.name() + "' has no command: launch with task:=command";
    return;
  }
  try {
    task.setCommand(static_cast<int>(req.env_id), {req.x, req.y}, req.hold);
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
        stepWith(pending_targets_.data(), pending_targets_.size());
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
    stepWith(current_targets_.data(), current_targets_.size());
  } else {
    stepWith(zero_targets_.data(), zero_targets_.size());  // no fresh targets: brake
  }
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
