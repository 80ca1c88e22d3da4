#include "jetbot_rl/env/batched_env.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "env/action_layout.h"
#include "env/env_physics.h"
#include "env/env_randomizer.h"
#include "env/thread_pool.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/scene/movers.h"
#include "jetbot_rl/sensors/floor_image.h"
#include "jetbot_rl/tasks/task_capabilities.h"
#include "jetbot_rl/tasks/task_observer.h"
#include "robot/physics_model.h"
#include "scene/env_scene.h"
#include "scene/robot_team.h"
#include "sensors/camera_sensor.h"
#include "sensors/depth_scan_sensor.h"
#include "sensors/scan_sensor.h"

namespace jetbot_rl {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

BatchedEnv::BatchedEnv(RobotModelConstPtr robot, const EnvConfig& config,
                       std::unique_ptr<Task> task)
    : robot_(std::move(robot)), config_(config), task_(std::move(task)) {
  config_.validate();
  if (!robot_) throw ModelError("no robot model given");
  if (!task_) throw ConfigError("invalid task = null: a task object is required");
  drawer_ = capability<WorldDrawing>(*task_);
  config_.dof_names = resolvedDofNames(config_, *robot_);
  physics_ = std::make_unique<PhysicsModel>(robot_, config_);
  for (const auto& dof : physics_->dofs()) {
    wheel_low_.push_back(static_cast<float>(-dof.velocity_limit));
    wheel_high_.push_back(static_cast<float>(dof.velocity_limit));
    dof_limits_.push_back(dof);
  }
  actions_layout_ = std::make_unique<ActionLayout>(makeActionLayout(
      *robot_, config_, std::vector<double>(wheel_high_.begin(), wheel_high_.end())));
  const std::vector<CameraSpec> cameras =
      resolveCameras(config_.camera, *robot_, config_.controlDt());
  const std::optional<ScannerSpec> scanner =
      resolveScan(config_.scan, *robot_, cameras, config_.controlDt());
  const bool depth_scan = scanner && scanner->source == ScanSource::kCameraDepth;
  if (config_.world.enabled()) {
    config_.world.cut_height =
        resolveCutHeight(config_.world, scanner ? scannerHeight(*robot_, *scanner) : 0.0);
  }
  config_.world.read_visuals = !cameras.empty() && config_.camera.world_visuals;  // only if drawn
  scene_ = std::make_unique<EnvScene>(config_, robot_->footprintRadius(), drawer_,
                                      capability<FloorDrawing>(*task_));
  const int n = config_.numRows();
  if (scanner && !depth_scan) {  // a laser; a depth scan follows the camera
    scan_ = std::make_unique<ScanSensor>(*scanner, scene_->world(), n, config_.seed);
    sensors_.push_back(scan_.get());
  }
  // The floor image is read (and a bad one refused) with or without a camera to see it.
  std::shared_ptr<const FloorImage> floor;
  if (!config_.world.floor.empty()) {
    floor = std::make_shared<const FloorImage>(FloorImage::fromYamlFile(config_.world.floor));
  }
  // One scene of the world (its visuals, textures and robot shapes) for all the cameras.
  std::shared_ptr<CameraWorld> camera_world;
  if (!cameras.empty()) camera_world = std::make_shared<CameraWorld>(scene_->world(), floor);
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const bool batch = k == 0;  // resolveCameras() puts the batch's camera first
    cameras_.push_back(std::make_unique<CameraSensor>(
        cameras[k], static_cast<int>(k), *robot_, camera_world, n, config_.seed,
        batch ? &result_.images : nullptr, batch && config_.camera.batch_images,
        config_.camera.robot_visuals));
    sensors_.push_back(cameras_.back().get());
  }
  if (depth_scan) {  // after the camera: it reads the depth image of the same step
    scan_ = std::make_unique<DepthScanSensor>(*scanner, *cameras_[0], n, config_.seed);
    sensors_.push_back(scan_.get());
  }
  const SpeedLimitConfig& limit = config_.speed_limit;
  if (limit.enabled || limit.deployed) {
    if (!scan_) {
      throwInvalid(limit.enabled ? "speed_limit/enabled" : "speed_limit/deployed", "true",
                   "reads the scan ahead: the robot has no scanner (scan/link or a Gazebo ray "
                   "sensor)");
    }
    const ScannerSpec& s = scan_->spec();
    speed_limit_spec_ = makeSpeedLimitSpec(limit, *robot_, s);
    if (limit.enabled) {
      speed_limit_ = std::make_unique<SpeedLimit>(speed_limit_spec_, s.samples, s.min_angle,
                                                  s.angleIncrement(), s.range_min);
      speed_caps_.assign(static_cast<std::size_t>(n), 0.0f);
    }
  }
  TaskContext context;
  context.scanner = scanner ? &scan_->spec() : nullptr;
  context.world = scene_->world();
  if (!cameras_.empty() && config_.camera.batch_images) context.camera = &cameras_[0]->spec();
  context.action_dim = actionDim();
  context.control_dt = config_.controlDt();
  task_->attach(context);
  obs_dim_ = static_cast<int>(task_->observationNames().size());
  randomizer_ = std::make_unique<EnvRandomizer>(config_, *physics_, obs_dim_);
  const int num_obstacles = config_.world.obstacleSlots();
  const int num_movers = config_.movers.count();
  const int num_peers = config_.team.robots_per_env - 1;

  const int workers = std::min(config_.resolvedThreads(), n);
  pool_ = std::make_unique<ThreadPool>(workers);
  contexts_.resize(workers);
  envs_.resize(n);
  // Each thread builds its scratch and its block's envs, in parallel, so that their memory comes
  // from its own allocator arena and is first touched by the thread that steps it.
  pool_->run(workers, [this, n, num_obstacles, num_movers, num_peers](int w) {
    contexts_[w] = std::make_unique<WorkerContext>();
    for (int e = pool_->firstItemOf(w, n); e < pool_->firstItemOf(w + 1, n); ++e) {
      envs_[e] = std::make_unique<EnvPhysics>(*physics_, *contexts_[w], scene_->shapes(),
                                              num_obstacles, num_movers, num_peers);
    }
  });
  scene_->attach(envs_, robot_->visibleTop());
  for (std::size_t b = 1; b < robot_->bodies().size(); ++b) {
    joint_names_.push_back(robot_->bodies()[b].joint_name);
    dof_of_joint_.push_back(-1);
  }
  for (std::size_t d = 0; d < physics_->dofs().size(); ++d) {
    const int body = physics_->joints()[physics_->dofs()[d].joint].child;
    dof_of_joint_[body - 1] = static_cast<int>(d);
  }
  task_->resize(n);
  targets_.assign(static_cast<std::size_t>(n) * physics_->dofs().size(), 0.0f);
  actions_.assign(static_cast<std::size_t>(n) * actionDim(), 0.0f);
  outcome_.assign(n, 0);
  ended_.assign(n, 0);
  final_scratch_.assign(static_cast<std::size_t>(n) * obs_dim_, 0.0f);
  diverged_.assign(n, std::string());
  result_.observations.assign(static_cast<std::size_t>(n) * obs_dim_, 0.0f);
  result_.rewards.assign(n, 0.0f);
  result_.terminated.assign(n, 0);
  result_.truncated.assign(n, 0);
  result_.episode_steps.assign(n, 0);
  result_.reset_env_ids.reserve(n);
  result_.final_observations.reserve(static_cast<std::size_t>(n) * obs_dim_);
  collided_.assign(n, 0);
  reset();
}

BatchedEnv::~BatchedEnv() = default;

int BatchedEnv::numThreads() const { return pool_->size(); }

int BatchedEnv::actionDim() const { return static_cast<int>(actions_layout_->low.size()); }

const std::vector<float>& BatchedEnv::actionLow() const { return actions_layout_->low; }

const std::vector<float>& BatchedEnv::actionHigh() const { return actions_layout_->high; }

const ScannerSpec* BatchedEnv::scanner() const { return scan_ ? &scan_->spec() : nullptr; }

const CameraSpec* BatchedEnv::camera(int index) const {
  return index >= 0 && index < numCameras() ? &cameras_[index]->spec() : nullptr;
}

const StepResult& BatchedEnv::step(const float* actions, std::size_t count) {
  const int n = config_.numRows();
  checkActions(*actions_layout_, n, actions, count);
  if (speed_limit_) {  // on the scan each robot observed before acting
    const double v_max = actions_layout_->high[0];
    for (int e = 0; e < n; ++e) {
      speed_caps_[e] = static_cast<float>(speed_limit_->cap(scan_->ranges(e), v_max));
    }
  }
  actionsToTargets(*actions_layout_, n, wheel_low_.size(), actions, randomizer_->noisesActions(),
                   actions_.data(), targets_.data(), speed_limit_ ? speed_caps_.data() : nullptr);
  // An env's result does not depend on the thread that steps it: the thread lends it its
  // solver, which keeps nothing between envs.
  // The robots of one env are stepped by one thread (stepTeam()).
  if (scene_->team()) {
    pool_->runStealing(config_.num_envs, [this](int g, int w) { stepTeam(g, *contexts_[w]); });
  } else {
    pool_->runStealing(n, [this](int e, int w) { stepEnv(e, *contexts_[w]); });
  }
  ++result_.step;

  result_.reset_env_ids.clear();
  result_.final_observations.clear();
  result_.outcomes.clear();
  result_.divergences.clear();
  clearImages(result_.final_images);
  for (int e = 0; e < n; ++e) {
    if (!ended_[e]) continue;
    result_.reset_env_ids.push_back(static_cast<std::uint32_t>(e));
    if (keepsFinalImages()) cameras_[0]->appendFinal(e, result_.final_images);
    result_.outcomes.push_back(outcome_[e]);
    const float* f = &final_scratch_[static_cast<std::size_t>(e) * obs_dim_];
    result_.final_observations.insert(result_.final_observations.end(), f, f + obs_dim_);
    if (!diverged_[e].empty()) {
      result_.divergences.push_back({static_cast<std::uint32_t>(e), diverged_[e]});
      ++diverged_count_;
    }
  }
  return result_;
}

void BatchedEnv::stepEnv(int e, WorkerContext& context) {
  scene_->beginWorldStep(e);
  stepPhysics(e, context);
  sensePhysics(e);
  finishStep(e);
}

void BatchedEnv::stepPhysics(int e, WorkerContext& context) {
  EnvPhysics& physics = *envs_[e];
  physics.useContext(context);
  float* targets = &targets_[static_cast<std::size_t>(e) * wheel_low_.size()];
  if (randomizer_->shapesTargets()) randomizer_->shapeTargets(e, targets);
  physics.setTargets(targets);
  physics.clearCollided();
  // The people and the other robots move on with the robot: each physics step takes those near
  // it to where they are at its end (the other robots: none most steps).
  constexpr std::size_t kMaxKinds = 2;
  const std::vector<MovingBodies*>& moving = scene_->moving();
  bool move[kMaxKinds] = {false, false};
  for (std::size_t i = 0; i < moving.size(); ++i) {
    move[i] = moving[i]->beginStep(e, config_.controlDt());
  }
  for (int k = 0; k < config_.decimation; ++k) {
    for (std::size_t i = 0; i < moving.size(); ++i) {
      if (move[i]) moving[i]->moveIn(e, k, physics);
    }
    physics.step(config_.physics_dt);
  }
  ++result_.episode_steps[e];
  collided_[e] = physics.collidedWithPeer()    ? kHitRobot
                 : physics.collidedWithMover() ? kHitMover
                 : physics.collided()          ? kHitWorld
                                               : 0;
}

void BatchedEnv::sensePhysics(int e) {
  for (EnvSensor* sensor : sensors_) sensor->afterStep(e, scene_->sensed(e));
}

void BatchedEnv::finishStep(int e) {
  const int last_step = config_.maxEpisodeLength() - 1;
  EnvPhysics& physics = *envs_[e];
  // Isaac Lab order: dones, then rewards, then reset, then observations.
  const RootState state = physics.rootState();
  diverged_[e] = physics.divergence();
  const bool diverged = !diverged_[e].empty();
  if (diverged) diverged_[e] = "env " + std::to_string(e) + " diverged: " + diverged_[e];
  senseEnv(e);
  const bool terminated = !diverged && task_->terminated(e, state);
  const bool truncated =
      diverged || result_.episode_steps[e] >= static_cast<std::uint32_t>(last_step);
  result_.terminated[e] = terminated;
  result_.truncated[e] = truncated;
  result_.rewards[e] = diverged ? 0.0f : task_->reward(e, state);
  ended_[e] = terminated || truncated;
  if (ended_[e]) {
    outcome_[e] = static_cast<std::uint8_t>(terminated ? task_->outcome(e) : Outcome::kTimeOut);
    scene_->episodeEnded(e, outcome_[e] == static_cast<std::uint8_t>(Outcome::kSuccess));
    float* final_obs = &final_scratch_[static_cast<std::size_t>(e) * obs_dim_];
    task_->observe(e, state, final_obs);
    if (keepsFinalImages()) cameras_[0]->keepFinal(e);
    if (diverged) {
      std::fill(final_obs, final_obs + obs_dim_, 0.0f);  // NaN would poison learners
    } else if (randomizer_->noisesObservations()) {
      randomizer_->noiseObservation(e, final_obs);  // what the learner would have seen
    }
    if (scene_->team() && config_.team.rounds) {  // it waits for its round to end (stepTeam())
      scene_->team()->wait(e);
      physics.stop();  // standing (its odom and joint states say so)
      std::copy(final_obs, final_obs + obs_dim_,
                &result_.observations[static_cast<std::size_t>(e) * obs_dim_]);
      return;
    }
    resetEnv(e);
    senseEnv(e);
  }
  observeRow(e);
}

void BatchedEnv::observeRow(int e) {
  float* obs = &result_.observations[static_cast<std::size_t>(e) * obs_dim_];
  task_->observe(e, envs_[e]->rootState(), obs);
  if (randomizer_->noisesObservations()) randomizer_->noiseObservation(e, obs);
}

void BatchedEnv::resetEnv(int env) {
  EnvPhysics& physics = *envs_[env];
  physics.reset();
  if (randomizer_->drawsAtReset()) randomizer_->resetEnv(env, scene_->rng(env), physics);
  scene_->place(env);
  result_.episode_steps[env] = 0;
  task_->resetEnv(env, scene_->rng(env));
  collided_[env] = 0;
  std::fill_n(actions_.begin() + static_cast<std::ptrdiff_t>(env) * actionDim(), actionDim(), 0.0f);
  for (EnvSensor* sensor : sensors_) sensor->afterReset(env, scene_->sensed(env));
}

void BatchedEnv::senseEnv(int env) {
  EnvSenses senses;
  senses.scan = scan_ ? scan_->ranges(env) : nullptr;
  senses.collided = collided_[env] != 0;
  senses.collided_with_mover = collided_[env] == kHitMover;
  senses.collided_with_robot = collided_[env] == kHitRobot;
  senses.action = &actions_[static_cast<std::size_t>(env) * actionDim()];
  task_->sense(env, senses);
}

const StepResult& BatchedEnv::reset(const std::vector<std::uint32_t>& env_ids,
                                    std::optional<std::uint64_t> seed,
                                    const std::vector<std::uint32_t>& episode_steps) {
  const int n = config_.numRows();
  std::vector<std::uint8_t> selected(n, env_ids.empty() ? 1 : 0);
  for (std::uint32_t id : env_ids) {
    std::ostringstream s;
    if (id >= static_cast<std::uint32_t>(n)) {
      s << "env_ids: id " << id << " is out of range [0, " << n << ")";
      throw InputError(s.str());
    }
    if (selected[id]) {
      s << "env_ids: id " << id << " is listed twice";
      throw InputError(s.str());
    }
    selected[id] = 1;
  }
  const std::size_t count = env_ids.empty() ? static_cast<std::size_t>(n) : env_ids.size();
  if (!episode_steps.empty() && episode_steps.size() != count) {
    throw InputError("episode_steps: expected " + std::to_string(count) +
                     " values (one per reset env) or none, got " +
                     std::to_string(episode_steps.size()));
  }
  const auto last_start = static_cast<std::uint32_t>(config_.maxEpisodeLength() - 2);
  for (std::size_t k = 0; k < episode_steps.size(); ++k) {
    if (episode_steps[k] > last_start) {
      throw InputError("episode_steps[" + std::to_string(k) +
                       "] = " + std::to_string(episode_steps[k]) +
                       ": must be <= " + std::to_string(last_start) + " (max_episode_length - 2)");
    }
  }
  for (EnvSensor* sensor : sensors_) sensor->forgetNewReadings();
  scene_->beginReset(selected, seed);
  for (int e = 0; e < n; ++e) {
    if (!selected[e]) continue;
    if (seed) {
      scene_->reseed(e, *seed);
      randomizer_->reseed(e, *seed);
      for (EnvSensor* sensor : sensors_) sensor->reseed(e, *seed);
    }
    resetEnv(e);
  }
  scene_->endReset();
  // Each sees the others where they started (the first ones placed saw the later ones not yet).
  for (int e = 0; scene_->team() && e < n; ++e) {
    if (!selected[e]) continue;
    for (EnvSensor* sensor : sensors_) sensor->afterReset(e, scene_->sensed(e));
  }
  // Starting steps are given in env_ids order, which need not be ascending.
  for (std::size_t i = 0; i < episode_steps.size(); ++i) {
    const std::uint32_t id = env_ids.empty() ? static_cast<std::uint32_t>(i) : env_ids[i];
    result_.episode_steps[id] = episode_steps[i];
  }
  // With observation noise only the reset envs observe anew: the others keep their noise.
  const bool noisy = randomizer_->noisesObservations();
  for (int e = 0; e < n; ++e) {
    if (noisy && !selected[e]) continue;
    float* obs = &result_.observations[static_cast<std::size_t>(e) * obs_dim_];
    senseEnv(e);
    task_->observe(e, envs_[e]->rootState(), obs);
    if (noisy) randomizer_->noiseObservation(e, obs);
  }
  std::fill(result_.rewards.begin(), result_.rewards.end(), 0.0f);
  std::fill(result_.terminated.begin(), result_.terminated.end(), 0);
  std::fill(result_.truncated.begin(), result_.truncated.end(), 0);
  result_.reset_env_ids.clear();
  result_.final_observations.clear();
  result_.outcomes.clear();
  result_.divergences.clear();
  clearImages(result_.final_images);
  return result_;
}

bool BatchedEnv::keepsFinalImages() const {
  return !cameras_.empty() && config_.camera.batch_images;
}

BatchSpec BatchedEnv::spec() const {
  BatchSpec spec;
  spec.num_envs = numEnvs();
  spec.obs_dim = obsDim();
  spec.action_dim = actionDim();
  spec.action_low = actionLow();
  spec.action_high = actionHigh();
  spec.control_dt = controlDt();
  spec.max_episode_length = maxEpisodeLength();
  spec.task = task_->name();
  spec.observation_names = task_->observationNames();
  task_->observer().observationBounds(spec.observation_low, spec.observation_high);
  if (randomizer_->noisesObservations()) {  // noise may take any value anywhere
    std::fill(spec.observation_low.begin(), spec.observation_low.end(), -kInfinity);
    std::fill(spec.observation_high.begin(), spec.observation_high.end(), kInfinity);
  }
  spec.action_names = actions_layout_->names;
  spec.has_goals = task_->observer().hasGoal();
  task_->describeObservation(spec.observer);
  try {
    const DiffDrive drive = DiffDrive::fromEnv(*this);
    spec.observer.wheel_radius = drive.wheelRadius();
    spec.observer.wheel_separation = drive.wheelSeparation();
  } catch (const Error&) {
    // No differential drive: its kinematics stay 0.
  }
  spec.observer.footprint_radius = robot_->footprintRadius();
  if (config_.speed_limit.enabled || config_.speed_limit.deployed) {
    const SpeedLimitSpec& l = speed_limit_spec_;
    spec.observer.speed_limit_path = {l.front, l.left, l.right};
    spec.observer.speed_limit_distances = {l.stop_distance, l.slow_distance};
  }
  if (keepsFinalImages()) {
    const CameraSpec& camera = cameras_[0]->spec();
    if (camera.rgb) spec.image_kinds.push_back("rgb");
    if (camera.depth) spec.image_kinds.push_back("depth");
    if (camera.label) spec.image_kinds.push_back("label");
    spec.image_width = camera.intrinsics.width;
    spec.image_height = camera.intrinsics.height;
  }
  return spec;
}

void BatchedEnv::checkEnv(int env) const {
  if (env < 0 || env >= numEnvs()) {
    std::ostringstream s;
    s << "env " << env << " is out of range [0, " << numEnvs() << ")";
    throw InputError(s.str());
  }
}

double BatchedEnv::difficulty(int env) const {
  checkEnv(env);
  return scene_->difficulty(env);
}

const WorldModel* BatchedEnv::world() const { return scene_->world(); }

std::uint64_t BatchedEnv::obstaclesGivenUp() const { return scene_->obstaclesGivenUp(); }

std::uint64_t BatchedEnv::layoutsUnmade() const { return scene_->layoutsUnmade(); }

const MoverSet* BatchedEnv::movers() const { return scene_->movers(); }

std::uint64_t BatchedEnv::moversGivenUp() const { return scene_->moversGivenUp(); }

EnvView BatchedEnv::view(int env) const {
  checkEnv(env);
  return EnvView(*this, env);
}

void BatchedEnv::setRootState(int env, const RootState& state) {
  checkEnv(env);
  const bool finite = state.position.allFinite() && state.orientation.coeffs().allFinite() &&
                      state.com_linear_velocity.allFinite() && state.angular_velocity.allFinite();
  if (!finite || state.orientation.norm() < 1e-6) {
    throw InputError("root state of env " + std::to_string(env) +
                     ": values must be finite and the orientation a non-zero quaternion");
  }
  envs_[env]->setRootState(state);
  scene_->robotMoved(env);  // the others see it there
}

}  // namespace jetbot_rl
