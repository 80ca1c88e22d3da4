#include "jetbot_rl/tasks/navigation_task.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/planning/footprint_grid.h"
#include "jetbot_rl/planning/grid_planner.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/sensors/scan_reading.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {
namespace {

constexpr const char* kPathNames[] = {"path_remaining", "path_cos", "path_sin"};

double yawOf(const RootState& state) {
  const Eigen::Vector3d forward = state.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

/// ConfigError unless `spec` holds scan beams and a valid range for them (its field rules).
void checkScan(const ObserverSpec& spec) {
  if (spec.scan_beam_angles.empty()) {
    throw ConfigError(
        "the navigation task observes 0 scan beams: it needs at least one (scan_beam_angles)");
  }
  checkFieldRules(spec);
}

double checkedRange(const ObserverSpec& spec, std::size_t i) {
  checkScan(spec);
  return spec.scan_range[i];
}

}  // namespace

void takeObservationContract(const ObserverSpec& spec, NavigationConfig& config) {
  config.beams = static_cast<int>(spec.scan_beam_angles.size());
  config.log_beams = spec.log_beams;
  config.goal_radius = spec.goal_radius;
  config.path = spec.path_lookahead > 0.0;
  if (config.path) {
    config.path_lookahead = spec.path_lookahead;
    config.path_clearance = spec.path_clearance;
    config.path_clearance_cost = spec.path_clearance_cost;
  }
}

NavigationObserver::NavigationObserver(const ObserverSpec& spec, int action_dim)
    : NavigationObserver(static_cast<int>(spec.scan_beam_angles.size()), checkedRange(spec, 0),
                         checkedRange(spec, 1), action_dim, spec.goal_radius,
                         spec.path_lookahead > 0.0, spec.log_beams) {}

NavigationObserver::NavigationObserver(int beams, double range_min, double range_max,
                                       int action_dim, double goal_radius, bool path,
                                       bool log_beams)
    : beams_(beams),
      action_dim_(action_dim),
      range_min_(static_cast<float>(range_min)),
      range_max_(static_cast<float>(range_max)),
      goal_radius_(goal_radius),
      path_(path),
      log_beams_(log_beams),
      log_span_(std::log(range_max_ / range_min_)) {
  if (log_beams_ && !(range_min > 0.0)) {
    throwInvalid("nav/log_beams", "true",
                 "needs the scanner's range_min > 0 (log(range / range_min)); it is " +
                     std::to_string(range_min) + " m");
  }
}

std::vector<std::string> NavigationObserver::observationNames() const {
  std::vector<std::string> names;
  const std::string beam = log_beams_ ? "beam_log_" : "beam_";
  for (int i = 0; i < beams_; ++i) names.push_back(beam + std::to_string(i));
  for (const char* n : {"goal_distance", "goal_cos", "goal_sin"}) names.push_back(n);
  if (path_) {
    for (const char* n : kPathNames) names.push_back(n);
  }
  for (const char* n : {"lin_vel_b_x", "ang_vel_z"}) names.push_back(n);
  for (int a = 0; a < action_dim_; ++a) names.push_back("last_action_" + std::to_string(a));
  return names;
}

void NavigationObserver::observationBounds(std::vector<float>& low,
                                           std::vector<float>& high) const {
  TaskObserver::observationBounds(low, high);  // ±inf: speeds and the last actions
  for (int i = 0; i < beams_; ++i) {
    low[i] = log_beams_ ? 0.0f : range_min_ / range_max_;
    high[i] = 1.0f;
  }
  for (int at : path_ ? std::vector<int>{beams_, beams_ + 3} : std::vector<int>{beams_}) {
    low[at] = 0.0f;  // goal distance, path left
    for (int k = at + 1; k < at + 3; ++k) {
      low[k] = -1.0f;  // their cos, sin
      high[k] = 1.0f;
    }
  }
}

float NavigationObserver::beamValue(float range) const {
  float r = range;
  if (std::isnan(r) || r == kNoReturn) r = range_max_;
  if (r == kTooClose) r = range_min_;
  r = std::clamp(r, range_min_, range_max_);
  if (log_beams_) return std::min(1.0f, std::log(r / range_min_) / log_span_);
  return r / range_max_;
}

void NavigationObserver::observe(const MeasuredState& state, float* obs) const {
  std::size_t k = 0;
  for (int i = 0; i < beams_; ++i) obs[k++] = state.scan ? beamValue(state.scan[i]) : 1.0f;
  const Eigen::Rotation2Dd to_robot(-yawOf(state.root));
  const Eigen::Vector2d in_robot = to_robot * (state.goal - state.root.position.head<2>());
  const double d = in_robot.norm();
  obs[k++] = static_cast<float>(d);
  obs[k++] = static_cast<float>(d > 1e-9 ? in_robot.x() / d : 1.0);
  obs[k++] = static_cast<float>(d > 1e-9 ? in_robot.y() / d : 0.0);
  if (path_) {
    const Eigen::Vector2d ahead = to_robot * (state.lookahead - state.root.position.head<2>());
    const double a = ahead.norm();
    obs[k++] = static_cast<float>(state.path_remaining);
    obs[k++] = static_cast<float>(a > 1e-9 ? ahead.x() / a : 1.0);
    obs[k++] = static_cast<float>(a > 1e-9 ? ahead.y() / a : 0.0);
  }
  obs[k++] = static_cast<float>(state.root.comLinearVelocityBody().x());
  obs[k++] = static_cast<float>(state.root.angular_velocity.z());
  for (int a = 0; a < action_dim_; ++a) obs[k++] = state.last_action ? state.last_action[a] : 0.0f;
}

bool NavigationObserver::reached(const MeasuredState& state) const {
  return (state.goal - state.root.position.head<2>()).norm() < goal_radius_;
}

// Until attach() gives the scanner and the action size: a range of [0, 1] m and two actions.
NavigationTask::NavigationTask(const NavigationConfig& config, Variant variant)
    : config_(config),
      variant_(variant),
      observer_(config.beams, 0.0, 1.0, 2, config.goal_radius) {}

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
  // The observer of the contract the task writes: the one a robot elsewhere builds from it.
  ObserverSpec spec;
  describeObservation(spec);
  observer_ = NavigationObserver(spec, context.action_dim > 0 ? context.action_dim : 2);
  if (config_.path && !context.world) {
    throwInvalid("nav/path", "true",
                 "plans on the env's world: give it one (world/arena_size, world/map or "
                 "world/families)");
  }
}

std::vector<std::string> NavigationTask::arrowNames() const {
  if (config_.path) return {"goal", "path"};
  return {"goal"};
}

void NavigationTask::describeObservation(ObserverSpec& spec) const {
  spec.scan_beam_angles = beam_angles_;
  spec.scan_beam_width = beam_width_;
  spec.scan_range.clear();
  spec.scan_source.clear();
  spec.scan_heights.clear();
  if (context_.scanner) {
    spec.scan_range = {context_.scanner->range_min, context_.scanner->range_max};
    if (context_.scanner->source == ScanSource::kCameraDepth) {
      spec.scan_source = enumName(ScanSource::kCameraDepth);
      spec.scan_heights = {context_.scanner->min_height, context_.scanner->max_height};
    }
  }
  spec.log_beams = config_.log_beams;
  spec.goal_radius = config_.goal_radius;
  spec.path_lookahead = config_.path ? config_.path_lookahead : 0.0;
  spec.path_clearance = config_.path ? config_.path_clearance : 0.0;
  spec.path_clearance_cost = config_.path ? config_.path_clearance_cost : 0.0;
}

void NavigationTask::resize(int num_envs) {
  goals_.assign(num_envs, Eigen::Vector2d(config_.goal_distance[0], 0.0));
  drawn_.assign(num_envs, 0);
  senses_.assign(num_envs, EnvSenses());
  last_distance_.assign(num_envs, config_.goal_distance[0]);
  trackers_.assign(num_envs, PathTracker());
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
  const FootprintGrid* reach = draft ? draft->reach : nullptr;
  std::optional<FootprintGrid> static_reach;  // nav/goal_reachable in a world that is not generated
  if (world && !reach && config_.goal_reachable) {
    static_reach.emplace(*world, kFootprintGridResolution, world->robotRadius(),
                         obstacles ? *obstacles : std::vector<Obstacle>());
    static_reach->reachFrom(start);
    reach = &*static_reach;
  }
  double best_clearance = -1.0;
  bool found = !world;
  for (int k = 0; k < tries; ++k) {
    const double d = config_.goal_distance[0] +
                     (config_.goal_distance[1] - config_.goal_distance[0]) * rng.uniform();
    const double angle = 2.0 * kPi * rng.uniform();
    const Eigen::Vector2d goal = start + d * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const double clearance = world ? world->clearance(goal, obstacles) : 1e9;
    const bool inside = !world || ((world->region().isEmpty() || world->region().contains(goal)) &&
                                   world->inReach(goal));
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
  trackers_[env].reset({start, goals_[env]});  // until a path is planned on the layout
  return found;
}

void NavigationTask::layoutDrawn(int env, const WorldModel& world, const EnvLayout& layout) {
  if (!config_.path) return;
  const FootprintGrid grid(world, kFootprintGridResolution, world.robotRadius(), layout.obstacles,
                           config_.path_clearance);
  std::vector<Eigen::Vector2d> path;
  if (!planPath(grid, layout.start, goals_[env], config_.path_clearance_cost, path)) {
    ++unplanned_;  // the straight line stands in, as drawn
    return;
  }
  trackers_[env].reset(std::move(path));
  last_distance_[env] = trackers_[env].remaining(layout.start);
}

bool NavigationTask::drawInWorld(int env, Rng& rng, const WorldModel& world,
                                 const WorldDraft& draft, std::vector<Eigen::Vector2d>& keep_free) {
  bool found = true;
  if (draft.goal) {  // the world's (a circle swap's): nothing drawn
    goals_[env] = *draft.goal;
    last_distance_[env] = (*draft.goal - draft.start).norm();
    position_[env] = draft.start;
    trackers_[env].reset({draft.start, *draft.goal});
  } else {
    found = drawGoalAround(env, rng, draft.start, &world, &draft);
  }
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
  trackers_.at(env).reset({position_.at(env), goal});
}

double NavigationTask::distance(int env, const RootState& state) const {
  const Eigen::Vector2d p = state.position.head<2>();
  if (!config_.path) return (goals_[env] - p).norm();
  trackers_[env].track(p);
  return trackers_[env].remaining(p);
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
  if (config_.path) {
    PathTracker& tracker = trackers_[env];
    tracker.track(position_[env]);
    measured.path_remaining = tracker.remaining(position_[env]);
    measured.lookahead = tracker.lookahead(config_.path_lookahead);
  }
  observer_.observe(measured, obs);
}

bool NavigationTask::terminated(int env, const RootState& state) const {
  Outcome o = Outcome::kTimeOut;
  MeasuredState measured;
  measured.root = state;
  measured.goal = goals_[env];
  if (senses_[env].collided) {
    // A robot or a mover among what it touched names the collision; else it was the world.
    o = senses_[env].collided_with_robot   ? Outcome::kCollisionRobot
        : senses_[env].collided_with_mover ? Outcome::kCollisionMover
                                           : Outcome::kCollision;
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
  if (o == Outcome::kCollision || o == Outcome::kCollisionMover || o == Outcome::kCollisionRobot) {
    r -= config_.collision_penalty;
  }
  return static_cast<float>(r);
}

Eigen::Vector2d NavigationTask::arrowDirection(int env, int arrow) const {
  const Eigen::Vector2d target =
      arrow == 1 ? trackers_.at(env).lookahead(config_.path_lookahead) : goals_.at(env);
  const Eigen::Vector2d rel = target - position_.at(env);
  return rel.norm() > 1e-9 ? Eigen::Vector2d(rel.normalized()) : Eigen::Vector2d::UnitX();
}

}  // namespace jetbot_rl
