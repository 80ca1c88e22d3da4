#include "jetbot_rl/navigation_task.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/laser_scanner.h"
#include "jetbot_rl/scan_reading.h"
#include "jetbot_rl/world_generation.h"
#include "jetbot_rl/world_model.h"

namespace jetbot_rl {
namespace {

constexpr double kPi = 3.14159265358979323846;

double yawOf(const RootState& state) {
  const Eigen::Vector3d forward = state.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

}  // namespace

NavigationObserver::NavigationObserver(int beams, double range_min, double range_max,
                                       int action_dim, double goal_radius)
    : beams_(beams),
      action_dim_(action_dim),
      range_min_(static_cast<float>(range_min)),
      range_max_(static_cast<float>(range_max)),
      goal_radius_(goal_radius) {}

std::vector<std::string> NavigationObserver::observationNames() const {
  std::vector<std::string> names;
  for (int i = 0; i < beams_; ++i) names.push_back("beam_" + std::to_string(i));
  for (const char* n : {"goal_distance", "goal_cos", "goal_sin", "lin_vel_b_x", "ang_vel_z"}) {
    names.push_back(n);
  }
  for (int a = 0; a < action_dim_; ++a) names.push_back("last_action_" + std::to_string(a));
  return names;
}

void NavigationObserver::observationBounds(std::vector<float>& low,
                                           std::vector<float>& high) const {
  TaskObserver::observationBounds(low, high);  // ±inf: speeds and the last actions
  for (int i = 0; i < beams_; ++i) {
    low[i] = range_min_ / range_max_;
    high[i] = 1.0f;
  }
  low[beams_] = 0.0f;  // goal distance
  for (int k = beams_ + 1; k < beams_ + 3; ++k) {
    low[k] = -1.0f;  // goal cos, sin
    high[k] = 1.0f;
  }
}

float NavigationObserver::beamValue(float range) const {
  float r = range;
  if (std::isnan(r) || r == kNoReturn) r = range_max_;
  if (r == kTooClose) r = range_min_;
  return std::clamp(r, range_min_, range_max_) / range_max_;
}

void NavigationObserver::observe(const MeasuredState& state, float* obs) const {
  std::size_t k = 0;
  for (int i = 0; i < beams_; ++i) obs[k++] = state.scan ? beamValue(state.scan[i]) : 1.0f;
  const double yaw = yawOf(state.root);
  const Eigen::Vector2d in_robot =
      Eigen::Rotation2Dd(-yaw) * (state.goal - state.root.position.head<2>());
  const double d = in_robot.norm();
  obs[k++] = static_cast<float>(d);
  obs[k++] = static_cast<float>(d > 1e-9 ? in_robot.x() / d : 1.0);
  obs[k++] = static_cast<float>(d > 1e-9 ? in_robot.y() / d : 0.0);
  obs[k++] = static_cast<float>(state.root.comLinearVelocityBody().x());
  obs[k++] = static_cast<float>(state.root.angular_velocity.z());
  for (int a = 0; a < action_dim_; ++a) obs[k++] = state.last_action ? state.last_action[a] : 0.0f;
}

bool NavigationObserver::reached(const MeasuredState& state) const {
  return (state.goal - state.root.position.head<2>()).norm() < goal_radius_;
}

// Until attach() gives the scanner and the action size: a range of [0, 1] m and two actions.
NavigationTask::NavigationTask(const NavigationConfig& config, Variant variant)
    : config_(config), variant_(variant), observer_(config.beams, 0.0, 1.0, 2, config.goal_radius) {
  validateConfig(config_);
}

void NavigationTask::attach(const TaskContext& context) {
  context_ = context;
  if (!context.scanner) {
    throw ConfigError(
        "invalid task = navigation: it observes a laser scan; give the robot a scanner (scan/link, "
        "or a robot description with a Gazebo ray sensor block)");
  }
  if (config_.beams > context.scanner->samples) {
    throwInvalid(
        "nav/beams", config_.beams,
        "must be <= the scanner's samples (" + std::to_string(context.scanner->samples) + ")");
  }
  // Beam i: the smallest reading of its share of the samples, [floor(i S / K), floor((i + 1) S /
  // K)) as angles, so that the beams read the whole scan (with S = K, sample i itself).
  const ScannerSpec& scanner = *context.scanner;
  // One sample has no spacing: any positive increment reads it.
  scan_increment_ = scanner.samples > 1 ? scanner.angleIncrement() : 1.0;
  beam_angles_.clear();
  for (int i = 0; i < config_.beams; ++i) {
    const long long k = static_cast<long long>(i) * scanner.samples / config_.beams;
    beam_angles_.push_back(scanner.min_angle + static_cast<double>(k) * scanner.angleIncrement());
  }
  beam_width_ = scanner.samples > 1
                    ? scan_increment_ * static_cast<double>(scanner.samples) / config_.beams
                    : 0.0;
  observer_ =
      NavigationObserver(config_.beams, context.scanner->range_min, context.scanner->range_max,
                         context.action_dim > 0 ? context.action_dim : 2, config_.goal_radius);
}

std::vector<double> NavigationTask::scanBeamAngles() const { return beam_angles_; }

void NavigationTask::resize(int num_envs) {
  goals_.assign(num_envs, Eigen::Vector2d(config_.goal_distance[0], 0.0));
  drawn_.assign(num_envs, 0);
  senses_.assign(num_envs, EnvSenses());
  last_distance_.assign(num_envs, config_.goal_distance[0]);
  outcome_.assign(num_envs, static_cast<unsigned char>(Outcome::kTimeOut));
  position_.assign(num_envs, Eigen::Vector2d::Zero());
}

bool NavigationTask::drawGoalAround(int env, Rng& rng, const Eigen::Vector2d& start,
                                    const WorldModel* world, const WorldDraft* draft) {
  // Distance and direction from the env's stream; with a world, redrawn until the goal keeps its
  // clearance and, in a generated layout, has a path from the start (otherwise the clearest
  // draw stands in, and false is returned).
  const int tries = world ? world->config().placement_tries : 1;
  const std::vector<Obstacle>* obstacles = draft ? draft->obstacles : nullptr;
  const ReachableGrid* reach = draft ? draft->reach : nullptr;
  double best_clearance = -1.0;
  bool found = !world;
  for (int k = 0; k < tries; ++k) {
    const double d = config_.goal_distance[0] +
                     (config_.goal_distance[1] - config_.goal_distance[0]) * rng.uniform();
    const double angle = 2.0 * kPi * rng.uniform();
    const Eigen::Vector2d goal = start + d * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const double clearance = world ? world->clearance(goal, obstacles) : 1e9;
    const bool inside = !world || world->region().isEmpty() || world->region().contains(goal);
    const bool usable = inside && (!reach || reach->reachable(goal));
    if (usable && clearance > best_clearance) {
      best_clearance = clearance;
      goals_[env] = goal;
    }
    if (usable && clearance >= config_.goal_clearance) {
      found = true;
      break;
    }
  }
  last_distance_[env] = (goals_[env] - start).norm();
  position_[env] = start;
  return found;
}

bool NavigationTask::drawInWorld(int env, Rng& rng, const WorldModel& world,
                                 const WorldDraft& draft, std::vector<Eigen::Vector2d>& keep_free) {
  const bool found = drawGoalAround(env, rng, draft.start, &world, &draft);
  drawn_[env] = 1;
  keep_free.push_back(goals_[env]);
  return found;
}

void NavigationTask::resetEnv(int env, Rng& rng) {
  if (!drawn_[env]) drawGoalAround(env, rng, Eigen::Vector2d::Zero(), nullptr, nullptr);
  drawn_[env] = 0;
  outcome_[env] = static_cast<unsigned char>(Outcome::kTimeOut);
}

void NavigationTask::sense(int env, const EnvSenses& senses) { senses_[env] = senses; }

void NavigationTask::setGoal(int env, const Eigen::Vector2d& goal) {
  if (!goal.allFinite()) throw InputError("goal of env " + std::to_string(env) + " is not finite");
  goals_.at(env) = goal;
}

double NavigationTask::distance(int env, const RootState& state) const {
  return (goals_[env] - state.position.head<2>()).norm();
}

void NavigationTask::observe(int env, const RootState& state, float* obs) const {
  thread_local std::vector<float> beams;
  beams.resize(beam_angles_.size());
  const float* scan = senses_[env].scan;
  if (scan) {
    const ScanView view{scan, context_.scanner->samples, context_.scanner->min_angle,
                        scan_increment_};
    std::string error;
    if (!readBeams(view, beam_angles_, beam_width_, beams.data(), error)) {
      std::fill(beams.begin(), beams.end(), std::numeric_limits<float>::quiet_NaN());
    }
  }
  MeasuredState measured;
  measured.root = state;
  measured.scan = scan ? beams.data() : nullptr;
  measured.goal = goals_[env];
  measured.last_action = senses_[env].action;
  position_[env] = state.position.head<2>();
  observer_.observe(measured, obs);
}

bool NavigationTask::terminated(int env, const RootState& state) const {
  Outcome o = Outcome::kTimeOut;
  MeasuredState measured;
  measured.root = state;
  measured.goal = goals_[env];
  if (senses_[env].collided) {
    o = Outcome::kCollision;
  } else if (observer_.reached(measured)) {
    o = Outcome::kSuccess;
  }
  outcome_[env] = static_cast<unsigned char>(o);
  return o != Outcome::kTimeOut;
}

float NavigationTask::reward(int env, const RootState& state) const {
  const double d = distance(env, state);
  double r = -config_.step_cost;
  if (variant_ == Variant::kProgress) r += config_.progress_reward * (last_distance_[env] - d);
  if (config_.proximity_penalty > 0.0 && senses_[env].scan) {
    const ScannerSpec& scanner = *context_.scanner;
    double closest = scanner.range_max;
    for (int k = 0; k < scanner.samples; ++k) {
      closest = std::min(closest, static_cast<double>(finiteRange(senses_[env].scan[k], scanner)));
    }
    if (closest < config_.proximity_distance) {
      r -= config_.proximity_penalty * (1.0 - closest / config_.proximity_distance);
    }
  }
  last_distance_[env] = d;
  const auto o = static_cast<Outcome>(outcome_[env]);
  if (o == Outcome::kSuccess) r += config_.goal_reward;
  if (o == Outcome::kCollision) r -= config_.collision_penalty;
  return static_cast<float>(r);
}

Eigen::Vector2d NavigationTask::arrowDirection(int env, int) const {
  const Eigen::Vector2d rel = goals_.at(env) - position_.at(env);
  return rel.norm() > 1e-9 ? Eigen::Vector2d(rel.normalized()) : Eigen::Vector2d::UnitX();
}

}  // namespace jetbot_rl
