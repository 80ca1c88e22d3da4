#include "jetbot_rl/batched_env.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "action_layout.h"
#include "env_randomizer.h"
#include "env_world.h"
#include "jetbot_rl/errors.h"
#include "physics_model.h"
#include "thread_pool.h"
#include "world_shapes.h"

namespace jetbot_rl {

namespace {

// Scan noise of env e: the stream of env id e + kScanStream (another than its noise stream's).
constexpr std::uint64_t kScanStream = 1ULL << 41;

Eigen::Isometry3d toEigen(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  out.translation() << t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z();
  return out;
}

constexpr std::uint64_t pack(int front, int back) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(back)) << 32 |
         static_cast<std::uint32_t>(front);
}

/// Takes the first (or, from the back, the last) env of a block's unstepped range; -1 when empty.
int claim(std::atomic<std::uint64_t>& range, bool from_back) {
  std::uint64_t r = range.load(std::memory_order_relaxed);
  for (;;) {
    const int front = static_cast<int>(r & 0xffffffffu);
    const int back = static_cast<int>(r >> 32);
    if (front >= back) return -1;
    const std::uint64_t rest = from_back ? pack(front, back - 1) : pack(front + 1, back);
    if (range.compare_exchange_weak(r, rest, std::memory_order_relaxed)) {
      return from_back ? back - 1 : front;
    }
  }
}

}  // namespace

BatchedEnv::BatchedEnv(RobotModelConstPtr robot, const EnvConfig& config,
                       std::unique_ptr<Task> task)
    : robot_(std::move(robot)), config_(config), task_(std::move(task)) {
  config_.validate();
  if (!robot_) throw ModelError("no robot model given");
  if (!task_) throw ConfigError("invalid task = null: a task object is required");
  config_.dof_names = resolvedDofNames(config_, *robot_);
  physics_ = std::make_unique<PhysicsModel>(robot_, config_);
  for (const auto& dof : physics_->dofs()) {
    wheel_low_.push_back(static_cast<float>(-dof.velocity_limit));
    wheel_high_.push_back(static_cast<float>(dof.velocity_limit));
    dof_limits_.push_back(dof);
  }
  ActionLayout actions = makeActionLayout(
      *robot_, config_, std::vector<double>(wheel_high_.begin(), wheel_high_.end()));
  action_low_ = std::move(actions.low);
  action_high_ = std::move(actions.high);
  action_names_ = std::move(actions.names);
  drive_ = std::move(actions.drive);
  if (config_.world.enabled()) {
    world_ = std::make_shared<const WorldModel>(config_.world, robot_->footprintRadius());
    world_shapes_ = std::make_unique<WorldShapes>(*world_);
  }
  scanner_ = resolveScanner(config_.scan, *robot_, config_.controlDt());
  TaskContext context;
  context.scanner = scanner_ ? &*scanner_ : nullptr;
  context.world = world_.get();
  context.action_dim = actionDim();
  context.control_dt = config_.controlDt();
  task_->attach(context);
  obs_dim_ = static_cast<int>(task_->observationNames().size());
  randomizer_ = std::make_unique<EnvRandomizer>(config_, *physics_, obs_dim_);
  const int num_obstacles = config_.world.num_boxes + config_.world.num_cylinders;

  const int n = config_.num_envs;
  const int workers = std::min(config_.resolvedThreads(), n);
  pool_ = std::make_unique<ThreadPool>(workers);
  blocks_ = std::make_unique<Block[]>(workers);
  contexts_.resize(workers);
  worlds_.resize(n);
  // Each thread builds its scratch and its block's worlds, in parallel, so that their memory comes
  // from its own allocator arena and is first touched by the thread that steps it.
  pool_->run(workers, [this, num_obstacles](int w) {
    contexts_[w] = std::make_unique<WorkerContext>();
    for (int e = firstEnvOf(w); e < firstEnvOf(w + 1); ++e) {
      worlds_[e] =
          std::make_unique<EnvWorld>(*physics_, *contexts_[w], world_shapes_.get(), num_obstacles);
    }
  });
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
  for (int e = 0; e < n; ++e) rngs_.emplace_back(config_.seed, e);
  layouts_.resize(n);
  collided_.assign(n, 0);
  if (scanner_) {
    scans_.assign(static_cast<std::size_t>(n) * scanner_->samples, kNoReturn);
    scan_age_.assign(n, 0);
    scanned_.assign(n, 0);
    for (int e = 0; e < n; ++e) scan_noise_.emplace_back(config_.seed, e + kScanStream);
  }
  reset();
}

BatchedEnv::~BatchedEnv() = default;

int BatchedEnv::numThreads() const { return pool_->size(); }

// Envs are split into contiguous blocks, one per worker.
int BatchedEnv::firstEnvOf(int worker) const {
  return static_cast<int>(static_cast<long long>(worker) * config_.num_envs / pool_->size());
}

const StepResult& BatchedEnv::step(const float* actions, std::size_t count) {
  const int n = config_.num_envs;
  const int a = actionDim();
  const std::size_t expected = static_cast<std::size_t>(n) * a;
  if (actions == nullptr || count != expected) {
    std::ostringstream s;
    s << "actions: expected " << expected << " values (" << n << " envs x " << a << " dofs), got "
      << (actions == nullptr ? 0 : count);
    throw InputError(s.str());
  }
  for (std::size_t i = 0; i < expected; ++i) {
    if (!std::isfinite(actions[i])) {
      std::ostringstream s;
      s << "actions[env " << i / a << ", " << action_names_[i % a] << "] = " << actions[i]
        << " is not finite";
      throw InputError(s.str());
    }
  }
  // The last action within its bounds, for the tasks that observe it.
  for (std::size_t i = 0; i < expected; ++i) {
    actions_[i] = std::clamp(actions[i], action_low_[i % a], action_high_[i % a]);
  }
  if (drive_) {
    // (v, omega) -> wheel targets: DiffDrive keeps the curvature within the wheels' limits.
    const std::size_t dofs = wheel_low_.size();
    for (int e = 0; e < n; ++e) {
      const std::array<double, 2> wheels =
          drive_->wheelTargets({actions_[2 * e], actions_[2 * e + 1]});
      for (std::size_t d = 0; d < dofs; ++d) targets_[e * dofs + d] = static_cast<float>(wheels[d]);
    }
  } else if (randomizer_->noisesActions()) {
    std::copy(actions, actions + expected, targets_.begin());  // noise first, then clamping
  } else {
    std::copy(actions_.begin(), actions_.end(), targets_.begin());
  }

  for (int w = 0; w < pool_->size(); ++w) {
    blocks_[w].range.store(pack(firstEnvOf(w), firstEnvOf(w + 1)), std::memory_order_relaxed);
  }
  pool_->run(pool_->size(), [this](int w) { stepWorker(w); });
  ++result_.step;

  result_.reset_env_ids.clear();
  result_.final_observations.clear();
  result_.outcomes.clear();
  result_.divergences.clear();
  for (int e = 0; e < n; ++e) {
    if (!ended_[e]) continue;
    result_.reset_env_ids.push_back(static_cast<std::uint32_t>(e));
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

// Worker w steps its own block front to back, then takes envs from the back of the others'
// blocks: a thread that was held up (a descheduled core, slower envs) no longer holds the whole
// step up, and a helper never works next to the block's owner. An env's result does not depend
// on the thread that steps it: the thread lends it its solver, which keeps nothing between worlds.
void BatchedEnv::stepWorker(int w) {
  WorkerContext& context = *contexts_[w];
  for (int e; (e = claim(blocks_[w].range, false)) >= 0;) stepEnv(e, context);
  const int workers = pool_->size();
  for (int k = 1; k < workers; ++k) {
    auto& range = blocks_[(w + k) % workers].range;
    for (int e; (e = claim(range, true)) >= 0;) stepEnv(e, context);
  }
}

void BatchedEnv::stepEnv(int e, WorkerContext& context) {
  const int last_step = config_.maxEpisodeLength() - 1;
  EnvWorld& world = *worlds_[e];
  world.useContext(context);
  float* targets = &targets_[static_cast<std::size_t>(e) * wheel_low_.size()];
  if (randomizer_->shapesTargets()) randomizer_->shapeTargets(e, targets);
  world.setTargets(targets);
  world.clearCollided();
  for (int k = 0; k < config_.decimation; ++k) world.step(config_.physics_dt);
  ++result_.episode_steps[e];
  collided_[e] = world.collided();
  if (scanner_) {
    scanned_[e] = 0;
    if (++scan_age_[e] >= static_cast<std::uint32_t>(scanner_->update_every)) scanEnv(e);
  }

  // Isaac Lab order: dones, then rewards, then reset, then observations.
  RootState state = world.rootState();
  diverged_[e] = world.divergence();
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
    float* final_obs = &final_scratch_[static_cast<std::size_t>(e) * obs_dim_];
    task_->observe(e, state, final_obs);
    if (diverged) {
      std::fill(final_obs, final_obs + obs_dim_, 0.0f);  // NaN would poison learners
    } else if (randomizer_->noisesObservations()) {
      randomizer_->noiseObservation(e, final_obs);  // what the learner would have seen
    }
    resetEnv(e);
    state = world.rootState();
    senseEnv(e);
  }
  float* obs = &result_.observations[static_cast<std::size_t>(e) * obs_dim_];
  task_->observe(e, state, obs);
  if (randomizer_->noisesObservations()) randomizer_->noiseObservation(e, obs);
}

void BatchedEnv::resetEnv(int env) {
  EnvWorld& world = *worlds_[env];
  world.reset();
  if (randomizer_->drawsAtReset()) randomizer_->resetEnv(env, rngs_[env], world);
  if (world_) {
    // The start first, then the obstacles around it, from the env's own stream.
    EnvLayout& layout = layouts_[env];
    world_->drawStart(rngs_[env], layout);
    world.moveRobot(layout.start);
    std::vector<Eigen::Vector2d> keep_free{layout.start};
    task_->drawInWorld(env, rngs_[env], *world_, layout.start, keep_free);
    world_->drawObstacles(rngs_[env], keep_free, layout);
    world.setObstacles(layout.obstacles);
    given_up_ += static_cast<std::uint64_t>(layout.given_up);
  }
  result_.episode_steps[env] = 0;
  task_->resetEnv(env, rngs_[env]);
  collided_[env] = 0;
  std::fill_n(actions_.begin() + static_cast<std::ptrdiff_t>(env) * actionDim(), actionDim(), 0.0f);
  if (scanner_) scanEnv(env);
}

void BatchedEnv::senseEnv(int env) {
  EnvSenses senses;
  senses.scan = scanner_ ? &scans_[static_cast<std::size_t>(env) * scanner_->samples] : nullptr;
  senses.collided = collided_[env] != 0;
  senses.action = &actions_[static_cast<std::size_t>(env) * actionDim()];
  task_->sense(env, senses);
}

void BatchedEnv::scanEnv(int env) {
  const Eigen::Isometry3d sensor =
      toEigen(worlds_[env]->linkPose(scanner_->body)) * scanner_->pose_in_body;
  castScan(*scanner_, world_.get(), layouts_[env].obstacles, sensor, scan_noise_[env],
           &scans_[static_cast<std::size_t>(env) * scanner_->samples]);
  scan_age_[env] = 0;
  scanned_[env] = 1;
}

const StepResult& BatchedEnv::reset(const std::vector<std::uint32_t>& env_ids,
                                    std::optional<std::uint64_t> seed,
                                    const std::vector<std::uint32_t>& episode_steps) {
  const int n = config_.num_envs;
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
  if (scanner_) std::fill(scanned_.begin(), scanned_.end(), 0);
  for (int e = 0; e < n; ++e) {
    if (!selected[e]) continue;
    if (seed) {
      rngs_[e] = Rng(*seed, e);
      randomizer_->reseed(e, *seed);
      if (scanner_) scan_noise_[e] = Rng(*seed, e + kScanStream);
    }
    resetEnv(e);
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
    task_->observe(e, worlds_[e]->rootState(), obs);
    if (noisy) randomizer_->noiseObservation(e, obs);
  }
  std::fill(result_.rewards.begin(), result_.rewards.end(), 0.0f);
  std::fill(result_.terminated.begin(), result_.terminated.end(), 0);
  std::fill(result_.truncated.begin(), result_.truncated.end(), 0);
  result_.reset_env_ids.clear();
  result_.final_observations.clear();
  result_.outcomes.clear();
  result_.divergences.clear();
  return result_;
}

BatchSpec BatchedEnv::spec() const {
  BatchSpec spec;
  spec.num_envs = numEnvs();
  spec.obs_dim = obsDim();
  spec.action_dim = actionDim();
  spec.action_low = action_low_;
  spec.action_high = action_high_;
  spec.control_dt = controlDt();
  spec.max_episode_length = maxEpisodeLength();
  spec.task = task_->name();
  spec.observation_names = task_->observationNames();
  spec.action_names = action_names_;
  spec.scan_beam_angles = task_->scanBeamAngles();
  if (!spec.scan_beam_angles.empty()) spec.scan_range = {scanner_->range_min, scanner_->range_max};
  return spec;
}

void BatchedEnv::checkEnv(int env) const {
  if (env < 0 || env >= config_.num_envs) {
    std::ostringstream s;
    s << "env " << env << " is out of range [0, " << config_.num_envs << ")";
    throw InputError(s.str());
  }
}

Eigen::Vector3d BatchedEnv::envOrigin(int env) const {
  checkEnv(env);
  // Isaac Sim's GridCloner layout: rows along -x, columns along +y, centred on the world origin.
  const int n = config_.num_envs;
  const int per_row = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  const int rows = (n + per_row - 1) / per_row;
  const int cols = (n + rows - 1) / rows;
  const double spacing = config_.env_spacing;
  const int row = env / cols;
  const int col = env % cols;
  return {0.5 * spacing * (rows - 1) - row * spacing, col * spacing - 0.5 * spacing * (cols - 1),
          0.0};
}

RootState BatchedEnv::rootState(int env) const {
  checkEnv(env);
  return worlds_[env]->rootState();
}

void BatchedEnv::setRootState(int env, const RootState& state) {
  checkEnv(env);
  const bool finite = state.position.allFinite() && state.orientation.coeffs().allFinite() &&
                      state.com_linear_velocity.allFinite() && state.angular_velocity.allFinite();
  if (!finite || state.orientation.norm() < 1e-6) {
    throw InputError("root state of env " + std::to_string(env) +
                     ": values must be finite and the orientation a non-zero quaternion");
  }
  worlds_[env]->setRootState(state);
}

std::vector<LinkPose> BatchedEnv::linkPoses(int env) const {
  checkEnv(env);
  std::vector<LinkPose> poses;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  origin.translation() = envOrigin(env);
  const auto& bodies = robot_->bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const btTransform t = worlds_[env]->linkPose(static_cast<int>(b));
    const btQuaternion q = t.getRotation();
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
    body.translation() << t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z();
    for (const auto& link : bodies[b].links) {
      poses.push_back({link.name, origin * body * link.offset});
    }
  }
  return poses;
}

double BatchedEnv::maxJointError(int env) const {
  checkEnv(env);
  return worlds_[env]->maxJointError();
}

double BatchedEnv::dofVelocity(int env, int dof) const {
  checkEnv(env);
  if (dof < 0 || dof >= static_cast<int>(wheel_low_.size()))
    throw InputError("dof " + std::to_string(dof) + " is out of range");
  return worlds_[env]->dofVelocity(dof);
}

void BatchedEnv::jointStates(int env, JointStates& out) const {
  checkEnv(env);
  const EnvWorld& world = *worlds_[env];
  const std::size_t n = joint_names_.size();
  out.position.resize(n);
  out.velocity.resize(n);
  out.effort.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const int body = static_cast<int>(j) + 1;  // joint j drives body j + 1
    out.position[j] = world.jointPosition(body);
    out.velocity[j] = world.jointVelocity(body);
    out.effort[j] = dof_of_joint_[j] < 0 ? 0.0 : world.dofEffort(dof_of_joint_[j]);
  }
}

RandomizationDraw BatchedEnv::randomization(int env) const {
  checkEnv(env);
  return randomizer_->values(env);
}

const EnvLayout& BatchedEnv::layout(int env) const {
  checkEnv(env);
  return layouts_[env];
}

bool BatchedEnv::collided(int env) const {
  checkEnv(env);
  return collided_[env] != 0;
}

const float* BatchedEnv::scan(int env) const {
  checkEnv(env);
  return scanner_ ? &scans_[static_cast<std::size_t>(env) * scanner_->samples] : nullptr;
}

bool BatchedEnv::scanned(int env) const {
  checkEnv(env);
  return scanner_ && scanned_[env] != 0;
}

BodyTwist BatchedEnv::rootTwist(int env) const {
  checkEnv(env);
  BodyTwist twist;
  worlds_[env]->rootLinkTwist(twist.linear, twist.angular);
  return twist;
}

}  // namespace jetbot_rl
