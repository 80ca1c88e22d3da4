#include "jetbot_rl/ros/env_node/env_node.h"

#include <ros/callback_queue.h>
#include <ros/console.h>
#include <ros/transport_hints.h>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/bounded_service.h"
#include "jetbot_rl/ros/common/bounded_subscription.h"
#include "jetbot_rl/ros/common/msg_conversion.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/publication_flush.h"
#include "jetbot_rl/ros/common/robot_description.h"
#include "jetbot_rl/ros/common/stop_signal.h"
#include "jetbot_rl/ros/env_node/camera_output.h"
#include "jetbot_rl/ros/env_node/marker_publisher.h"
#include "jetbot_rl/ros/env_node/queue_size.h"
#include "jetbot_rl/ros/env_node/randomization_service.h"
#include "jetbot_rl/ros/env_node/robot_names.h"
#include "jetbot_rl/ros/env_node/robot_state_output.h"
#include "jetbot_rl/ros/env_node/scan_output.h"
#include "jetbot_rl/ros/env_node/sim_clock.h"
#include "jetbot_rl/ros/env_node/tf_publisher.h"
#include "jetbot_rl/sensors/camera_spec.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"

namespace jetbot_rl {
namespace {

// A lockstep learner has one message in flight.
// How long the last markers may take to be written [s]: SIGINT and SIGTERM end the node within
// this, waitForStop()'s 0.1 s and a little.
constexpr double kFlushTimeout = 0.5;
// The longest a state waits for roscpp's network thread [s, wall]: it passes every 0.1 s at the
// latest, and at once when woken.
constexpr double kPacingTimeout = 1.0;

}  // namespace

EnvNode::EnvNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeParams& params,
                 std::unique_ptr<BatchedEnv> env, std::optional<DiffDrive> drive)
    : params_(params),
      env_(std::move(env)),
      server_(*env_, params.mode, params.action_timeout),
      nh_(nh),
      pnh_(pnh),
      diagnostics_(nh_, pnh_.getNamespace().substr(1) + ": environment", enumName(params.mode),
                   env_->numEnvs()),
      pacer_(kEnvNodeQueueSize / 2, kPacingTimeout) {
  const int robot_view_envs = robotViewEnvs(params_);
  if (robot_view_envs > 0) {
    if (!drive) throw ConfigError("robot_view_envs > 0 needs the robot's differential drive");
    server_.enableCmdVel(*drive, robot_view_envs, params_.cmd_vel_timeout);
  }
  const EnvSpec spec = toMsg(env_->spec());
  spec_pub_ = pnh_.advertise<EnvSpec>("spec", 1, /*latch=*/true);
  spec_pub_.publish(spec);
  const RobotNames names(params_.env_prefix, params_.robot_prefix,
                         params_.setup.env.team.robots_per_env);
  env_step_queue_ = envStepQueueSize(ros::serialization::serializationLength(*server_.state()));
  outputs_.push_back(std::make_unique<EnvStepOutput>(pnh_, env_step_queue_, queues_));
  if (params_.publish_clock) outputs_.push_back(std::make_unique<ClockOutput>(nh_, queues_));
  outputs_.push_back(std::make_unique<EnvTfPublisher>(nh_, *env_, tfEnvs(params_), params_.tf_rate,
                                                      names, params_.publish_link_tf, queues_));
  outputs_.push_back(std::make_unique<RobotStateOutput>(nh_, *env_, robot_view_envs,
                                                        params_.odom_rate, names, queues_));
  outputs_.push_back(std::make_unique<ScanOutput>(nh_, *env_, robot_view_envs, names, queues_));
  for (int k = 0; k < env_->numCameras(); ++k) {
    outputs_.push_back(
        std::make_unique<CameraOutput>(nh_, *env_, k, robot_view_envs, names, queues_));
  }
  if (env_->world() && env_->world()->map()) {
    map_publisher_ = std::make_unique<MapPublisher>(nh_, *env_->world()->map(), names);
  }
  if (env_->world() && env_->world()->gazebo()) {
    geometry_publisher_ = std::make_unique<WorldGeometryPublisher>(nh_, *env_->world(), names);
  }
  outputs_.push_back(std::make_unique<EnvMarkerPublisher>(
      pnh_, *env_, params_.tf_envs, params_.tf_rate, params_.markers, queues_));
  {
    std::unique_lock<std::mutex> lock(state_mutex_);
    publish(lock, /*reset=*/true);  // initial /clock, EnvStep and tf batch
  }

  ros::NodeHandle inline_pnh(pnh_);
  inline_pnh.setCallbackQueue(&inline_queue_);
  // Anyone can send bytes: a message or request whose array or string lengths exceed its bytes
  // is refused before roscpp allocates for it, and counted.
  const auto refused = [this](const std::string& what) -> RefusalHandler {
    return [this, what](const std::string& reason) {
      std::lock_guard<std::mutex> lock(state_mutex_);
      server_.countMalformed(what + " refused unread: " + reason);
    };
  };
  targets_sub_ = subscribeBounded<WheelTargets>(
      inline_pnh, "wheel_targets", kEnvNodeQueueSize,
      [this](const WheelTargets::ConstPtr& msg) { onWheelTargets(msg); }, refused("wheel_targets"),
      ros::TransportHints().tcpNoDelay());
  step_srv_ = advertiseServiceBounded<Step>(
      inline_pnh, "step", [this](Step::Request& q, Step::Response& r) { return onStep(q, r); },
      refused("step"));
  reset_srv_ = advertiseServiceBounded<Reset>(
      inline_pnh, "reset", [this](Reset::Request& q, Reset::Response& r) { return onReset(q, r); },
      refused("reset"));
  set_command_srv_ = advertiseServiceBounded<SetCommand>(
      inline_pnh, "set_command",
      [this](SetCommand::Request& q, SetCommand::Response& r) { return onSetCommand(q, r); },
      refused("set_command"));
  ros::NodeHandle inline_nh(nh_);  // the robot view's topics: in the node's namespace
  inline_nh.setCallbackQueue(&inline_queue_);
  for (int e = 0; e < robot_view_envs; ++e) {
    const std::string topic = names.topic(e, "cmd_vel");
    cmd_vel_subs_.push_back(subscribeBounded<geometry_msgs::Twist>(
        inline_nh, topic, kEnvNodeQueueSize,
        [this, e](const geometry_msgs::Twist::ConstPtr& msg) { onCmdVel(e, msg); },
        refused(topic)));
  }
  // ---- domain randomisation: the values each env drew (docs/core.md, "Domain randomisation") ----
  get_randomization_srv_ =
      advertiseGetRandomization(inline_pnh, *env_, state_mutex_, refused("get_randomization"));
  // ----
  if (params_.mode == EnvMode::kRealtime) {
    const double period = env_->controlDt() / params_.real_time_factor;
    realtime_timer_ =
        nh_.createWallTimer(ros::WallDuration(period), &EnvNode::onRealtimeTimer, this);
  }
  diagnostics_timer_ = nh_.createWallTimer(ros::WallDuration(params_.diagnostic_period),
                                           &EnvNode::onDiagnosticsTimer, this);
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    diagnostics_.publish(counters(), env_->state().step);
  }
  ROS_INFO(
      "jetbot_env ready: %d envs, obs_dim %d, action_dim %d, control step %.6f s, %d threads, "
      "%s mode",
      env_->numEnvs(), env_->obsDim(), env_->actionDim(), env_->controlDt(), env_->numThreads(),
      enumName(params_.mode).c_str());
}

std::uint64_t EnvNode::step() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return env_->state().step;
}

void EnvNode::shutdown(double flush_timeout) {
  realtime_timer_.stop();
  diagnostics_timer_.stop();
  targets_sub_.shutdown();
  for (auto& sub : cmd_vel_subs_) sub.shutdown();
  step_srv_.shutdown();
  reset_srv_.shutdown();
  set_command_srv_.shutdown();
  get_randomization_srv_.shutdown();
  {
    // After any call in flight; a later one (already past roscpp) publishes nothing.
    std::lock_guard<std::mutex> state_lock(state_mutex_);
    std::lock_guard<std::mutex> publish_lock(publish_mutex_);
    finished_ = true;
    for (auto& output : outputs_) output->finish();
  }
  if (!flushPublications(flush_timeout) && ros::ok()) {
    ROS_WARN(
        "%s: the last messages were not all written within %.1f s (a subscriber that reads "
        "nothing?)",
        pnh_.getNamespace().c_str(), flush_timeout);
  }
}

void EnvNode::publish(std::unique_lock<std::mutex>& state_lock, bool reset) {
  if (finished_) return;
  const EnvStep::ConstPtr& msg = server_.state();
  // Taken before the capture: another thread's send() may still read what capture() overwrites
  // (a ~reset call during realtime ticks).
  std::lock_guard<std::mutex> publish_lock(publish_mutex_);
  for (auto& output : outputs_) output->capture(*env_, msg, reset);
  state_lock.unlock();
  // Back-to-back steps must not outrun roscpp's network thread (PublicationPacer).
  if (!pacer_.wait()) {
    ROS_WARN_THROTTLE(10.0,
                      "%s: roscpp's network thread made no pass for %.1f s: states published "
                      "meanwhile may push older ones out of subscriber queues (%llu times so far)",
                      pnh_.getNamespace().c_str(), kPacingTimeout,
                      static_cast<unsigned long long>(pacer_.timeouts()));
  }
  for (auto& output : outputs_) output->send();
  // Subscribers that fell behind lose their oldest messages here, counted (not in roscpp).
  for (const auto& lost : queues_.trim()) {
    ROS_WARN_THROTTLE(10.0,
                      "%s: %llu messages of %s not delivered: subscriber %s fell behind by more "
                      "than its queue (%llu undelivered on all topics so far; /diagnostics)",
                      pnh_.getNamespace().c_str(), static_cast<unsigned long long>(lost.dropped),
                      lost.topic.c_str(), lost.last_subscriber.c_str(),
                      static_cast<unsigned long long>(queues_.total()));
  }
}

void EnvNode::onWheelTargets(const WheelTargets::ConstPtr& msg) {
  std::unique_lock<std::mutex> lock(state_mutex_);
  if (server_.onWheelTargets(*msg, std::chrono::steady_clock::now())) publish(lock, false);
}

void EnvNode::onCmdVel(int env, const geometry_msgs::Twist::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  server_.onCmdVel(env, *msg, std::chrono::steady_clock::now());
}

bool EnvNode::onStep(Step::Request& req, Step::Response& res) {
  std::unique_lock<std::mutex> lock(state_mutex_);
  if (server_.onStep(req, res)) publish(lock, false);
  return true;
}

bool EnvNode::onReset(Reset::Request& req, Reset::Response& res) {
  std::unique_lock<std::mutex> lock(state_mutex_);
  if (server_.onReset(req, res)) publish(lock, true);
  return true;
}

bool EnvNode::onSetCommand(SetCommand::Request& req, SetCommand::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  server_.onSetCommand(req, res);
  return true;
}

void EnvNode::onRealtimeTimer(const ros::WallTimerEvent&) {
  std::unique_lock<std::mutex> lock(state_mutex_);
  server_.onTick(std::chrono::steady_clock::now());
  publish(lock, false);
}

void EnvNode::onDiagnosticsTimer(const ros::WallTimerEvent&) {
  std::unique_lock<std::mutex> lock(state_mutex_);
  const EnvCounters now = counters();
  const std::uint64_t step = env_->state().step;
  lock.unlock();
  diagnostics_.publish(now, step);
}

EnvCounters EnvNode::counters() const {
  EnvCounters c = server_.counters();
  c.paced_states = pacer_.waits();
  c.pacing_timeouts = pacer_.timeouts();
  c.env_step_queue = env_step_queue_;
  for (const auto& topic : queues_.counts()) {
    if (topic.dropped == 0) continue;
    c.undelivered += topic.dropped;
    if (!c.undelivered_by_topic.empty()) c.undelivered_by_topic += ", ";
    c.undelivered_by_topic += topic.topic + ": " + std::to_string(topic.dropped);
  }
  return c;
}

std::unique_ptr<EnvNode> makeEnvNode(ros::NodeHandle nh, ros::NodeHandle pnh) {
  const std::optional<NodeParams> loaded = loadParams<NodeParams>(pnh);
  if (!loaded) return nullptr;
  const NodeParams& params = *loaded;

  const std::string description_param = nh.resolveName("robot_description");
  std::unique_ptr<BatchedEnv> env;
  try {
    RobotModelConstPtr robot = loadRobotDescription(nh);
    try {
      env = makeEnv(robot, params.setup);
    } catch (const ConfigError& e) {  // a rule the env checks against the task or robot
      logParamError(pnh, e);
      return nullptr;
    } catch (const ModelError& e) {
      ROS_FATAL("%s: %s does not fit the parameters: %s", pnh.getNamespace().c_str(),
                description_param.c_str(), e.what());
      return nullptr;
    }
  } catch (const Error& e) {
    ROS_FATAL("%s: cannot use %s: %s", pnh.getNamespace().c_str(), description_param.c_str(),
              e.what());
    return nullptr;
  }
  for (const DofLimits& dof : env->dofLimits()) ROS_INFO("%s", describeDofLimits(dof).c_str());
  if (const auto& scanner = env->scanner()) ROS_INFO("%s", describeScanner(*scanner).c_str());
  for (int k = 0; k < env->numCameras(); ++k) {
    ROS_INFO("%s", describeCamera(*env->camera(k)).c_str());
  }
  if (const WorldModel* world = env->world()) {
    ROS_INFO("%s", describeWorld(*world).c_str());
    if (world->gazebo() && !world->gazebo()->skipped.empty()) {
      ROS_INFO("world/gazebo_world %s: not read: %s", world->gazebo()->path.c_str(),
               world->gazebo()->skipped.c_str());
    }
    if (world->gazebo()) {
      for (const std::string& w : world->gazebo()->warnings)
        ROS_WARN("world/gazebo_world %s", w.c_str());
    }
  }
  // The robot view's cmd_vel kinematics: required for robot envs, else only echoed and in ~spec.
  std::optional<DiffDrive> drive;
  try {
    drive = DiffDrive::fromEnv(*env);
    ROS_INFO("differential drive: %s", drive->describe().c_str());
  } catch (const Error& e) {
    if (robotViewEnvs(params) > 0) {
      ROS_FATAL(
          "%s: robot_view_envs = %d needs a differential drive of %s: %s (or set robot_view_envs "
          "0)",
          pnh.getNamespace().c_str(), params.robot_view_envs, description_param.c_str(), e.what());
      return nullptr;
    }
    ROS_INFO("no differential drive (robot_view_envs 0: not needed): %s", e.what());
  }
  return std::make_unique<EnvNode>(nh, pnh, params, std::move(env), drive);
}

int runEnvNode() {
  const std::atomic<bool>& stop = installStopSignalHandlers();
  ros::NodeHandle pnh("~");
  const std::unique_ptr<EnvNode> node = makeEnvNode(ros::NodeHandle(), pnh);
  if (!node) return 1;
  // Timers run here; topics and services in roscpp's network thread (inline_queue_).
  waitForStop(stop, ros::getGlobalCallbackQueue());
  if (stop.load()) ROS_INFO("%s: stopped by a signal", pnh.getNamespace().c_str());
  node->shutdown(kFlushTimeout);
  ros::shutdown();
  return 0;
}

}  // namespace jetbot_rl
