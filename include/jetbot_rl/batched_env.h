#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/diff_drive.h"
#include "jetbot_rl/dof_limits.h"
#include "jetbot_rl/env_config.h"
#include "jetbot_rl/laser_scanner.h"
#include "jetbot_rl/randomization.h"
#include "jetbot_rl/robot_model.h"
#include "jetbot_rl/step_result.h"
#include "jetbot_rl/task.h"
#include "jetbot_rl/world_model.h"

namespace jetbot_rl {

class EnvRandomizer;
class EnvWorld;
class PhysicsModel;
class ThreadPool;
class WorldShapes;
struct WorkerContext;

/// Pose of one URDF link in the world frame (env origin included).
struct LinkPose {
  std::string link;
  Eigen::Isometry3d pose;
};

/// One env's moving (revolute and continuous) joints, in BatchedEnv::jointNames() order.
struct JointStates {
  std::vector<double> position;  ///< [rad] about the URDF axis.
  std::vector<double> velocity;  ///< [rad/s].
  std::vector<double> effort;    ///< Drive torque of the last physics step [N m]; 0 if undriven.
};

/// Velocity of a frame, expressed in that frame.
struct BodyTwist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   ///< Of the frame's origin [m/s].
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  ///< [rad/s].
};

/**
 * A batch of independent Jetbot environments stepped by Bullet in parallel, with the step
 * semantics of Isaac Lab's DirectRLEnv (docs/core.md): decimated physics, time-outs at
 * max_episode_length - 1, auto-reset of ended envs, observations after the reset, and the final
 * observation of every ended episode kept.
 *
 * Each env has its own world in its own frame, so an env's trajectory depends only on its seed and
 * actions, bit for bit, whatever the thread count or the rest of the batch.
 */
class BatchedEnv {
 public:
  /// Validates `config` (ConfigError) and the dofs against the robot (ModelError), resets all envs.
  BatchedEnv(RobotModelConstPtr robot, const EnvConfig& config,
             std::unique_ptr<Task> task = std::make_unique<VelocityTask>());
  ~BatchedEnv();
  BatchedEnv(const BatchedEnv&) = delete;
  BatchedEnv& operator=(const BatchedEnv&) = delete;

  /// Advances every env by one control step with velocity targets [rad/s], num_envs x action_dim
  /// row-major; targets beyond a joint's velocity limit are clamped. Throws InputError naming the
  /// env and value for a wrong size or a non-finite value, and then nothing advances.
  const StepResult& step(const float* actions, std::size_t count);
  const StepResult& step(const std::vector<float>& actions) {
    return step(actions.data(), actions.size());
  }
  /// Resets the listed envs (all when empty) to the rest pose, reseeding their random streams
  /// first when `seed` is given; `episode_steps` is empty (every reset env starts at episode step
  /// 0) or holds the step each listed env starts at (< max_episode_length - 1: staggered starts).
  /// Throws InputError for an unknown or repeated id or a bad episode step; nothing is reset
  /// then. Rewards of the returned state are zero and no env is flagged; the step counter stays.
  const StepResult& reset(const std::vector<std::uint32_t>& env_ids = {},
                          std::optional<std::uint64_t> seed = std::nullopt,
                          const std::vector<std::uint32_t>& episode_steps = {});
  /// The batch after the last step() or reset().
  const StepResult& state() const { return result_; }

  int numEnvs() const { return config_.num_envs; }
  int obsDim() const { return obs_dim_; }
  int actionDim() const { return static_cast<int>(action_low_.size()); }
  int numThreads() const;
  double controlDt() const { return config_.controlDt(); }
  int maxEpisodeLength() const { return config_.maxEpisodeLength(); }
  const EnvConfig& config() const { return config_; }
  /// What a learner needs to know: sizes, action bounds, control step, names.
  BatchSpec spec() const;
  const Task& task() const { return *task_; }
  Task& task() { return *task_; }
  const RobotModel& robot() const { return *robot_; }
  /// Lower and upper action bounds: per dof -/+ its velocity limit [rad/s] (see dofLimits()),
  /// or with action_space twist -/+ the fastest v [m/s] and omega [rad/s] the wheels allow.
  const std::vector<float>& actionLow() const { return action_low_; }
  const std::vector<float>& actionHigh() const { return action_high_; }
  /// Limits of every dof in action order, and whether each came from the URDF or a parameter.
  const std::vector<DofLimits>& dofLimits() const { return dof_limits_; }
  /// Every revolute and continuous joint of the robot, driven or not, root to leaves.
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  /// Number of envs reset because they diverged, since construction.
  std::uint64_t divergedCount() const { return diverged_count_; }
  /// The values env `env` drew at its last reset (docs/core.md, "Domain randomisation"); the
  /// defaults when randomisation is off.
  RandomizationDraw randomization(int env) const;

  /// Origin of env `env` on the square grid, Isaac Lab's layout [m].
  Eigen::Vector3d envOrigin(int env) const;
  /// Root state of env `env` in its own frame.
  RootState rootState(int env) const;
  /// Overwrites env `env`'s root pose and velocity (for tests and tools); InputError when invalid.
  void setRootState(int env, const RootState& state);
  /// World pose of every URDF link of env `env`.
  std::vector<LinkPose> linkPoses(int env) const;
  /// Largest anchor separation over the env's joints [m].
  double maxJointError(int env) const;
  /// Velocity of dof `dof` of env `env` [rad/s].
  double dofVelocity(int env, int dof) const;
  /// Joint positions, velocities and drive efforts of env `env`, in jointNames() order; the
  /// vectors are resized, so a reused `out` allocates nothing.
  void jointStates(int env, JointStates& out) const;
  /// Twist of env `env`'s root link frame, in that frame (odometry's twist; the pose is
  /// rootState()'s position and orientation).
  BodyTwist rootTwist(int env) const;

  // ---- the world and the laser scanner (docs/world.md) ----
  /// The world every env shares (map, walls, region); nullptr when none is configured.
  const WorldModel* world() const { return world_.get(); }
  /// Env `env`'s layout of its current episode: start and obstacles.
  const EnvLayout& layout(int env) const;
  /// True when env `env`'s robot touched the map, a wall or an obstacle during the last step.
  bool collided(int env) const;
  /// Obstacles left out since construction because they did not fit (world/placement_tries).
  std::uint64_t obstaclesGivenUp() const { return given_up_; }
  /// The scanner in use, if any.
  const std::optional<ScannerSpec>& scanner() const { return scanner_; }
  /// Env `env`'s latest scan: scanner()->samples ranges [m] (REP 117: +inf beyond range_max,
  /// -inf below range_min); nullptr without a scanner.
  const float* scan(int env) const;
  /// True when env `env` took a new scan in the last step() or reset().
  bool scanned(int env) const;

 private:
  /// The envs of a worker's block not yet taken in the current step: [front, back) packed into
  /// one word (front in the low half), so that the owner (front) and helpers (back) claim envs
  /// with one compare-and-swap. One cache line each.
  struct alignas(64) Block {
    std::atomic<std::uint64_t> range{0};
  };

  void checkEnv(int env) const;
  void stepWorker(int worker);
  /// Steps env `env` with the stepping thread's scratch.
  void stepEnv(int env, WorkerContext& context);
  void resetEnv(int env);
  /// Gives the task env `env`'s senses (scan, contact, last action).
  void senseEnv(int env);
  /// Casts env `env`'s scan from its robot's current pose.
  void scanEnv(int env);
  int firstEnvOf(int worker) const;

  RobotModelConstPtr robot_;
  EnvConfig config_;
  std::unique_ptr<Task> task_;
  int obs_dim_ = 0;
  std::unique_ptr<PhysicsModel> physics_;
  std::unique_ptr<EnvRandomizer> randomizer_;
  std::unique_ptr<ThreadPool> pool_;
  std::vector<std::unique_ptr<WorkerContext>> contexts_;
  std::unique_ptr<Block[]> blocks_;  // per worker
  std::vector<std::unique_ptr<EnvWorld>> worlds_;
  std::vector<Rng> rngs_;
  std::vector<float> action_low_, action_high_;
  std::vector<float> wheel_low_, wheel_high_;  // per dof: its velocity limits
  std::vector<std::string> action_names_;      // the dofs', or linear_x, angular_z
  std::unique_ptr<DiffDrive> drive_;           // action_space twist: twist -> wheel targets
  std::vector<float> actions_;                 // per env: its last action (zeros after a reset)
  std::vector<std::uint8_t> outcome_;          // per env: how its ended episode ended
  std::vector<DofLimits> dof_limits_;
  std::vector<std::string> joint_names_;
  std::vector<int> dof_of_joint_;      // per jointNames() entry: its dof, or -1
  std::vector<float> targets_;         // clamped (raw with action noise) actions of the step
  std::vector<std::uint8_t> ended_;    // per env: ended in the current step
  std::vector<float> final_scratch_;   // per env final observation slot
  std::vector<std::string> diverged_;  // per env divergence reason of the current step
  StepResult result_;
  std::uint64_t diverged_count_ = 0;
  // The world (when configured) and the scanner (when the robot has one).
  std::shared_ptr<const WorldModel> world_;
  std::unique_ptr<WorldShapes> world_shapes_;
  std::vector<EnvLayout> layouts_;          // per env
  std::vector<std::uint8_t> collided_;      // per env: in the last step
  std::atomic<std::uint64_t> given_up_{0};  // obstacles left out
  std::optional<ScannerSpec> scanner_;
  std::vector<float> scans_;             // per env: samples ranges
  std::vector<std::uint32_t> scan_age_;  // per env: control steps since its last scan
  std::vector<std::uint8_t> scanned_;    // per env: a new scan in the last step or reset
  std::vector<Rng> scan_noise_;          // per env
};

}  // namespace jetbot_rl
