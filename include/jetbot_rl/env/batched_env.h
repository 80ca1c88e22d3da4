#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "jetbot_rl/env/env_config.h"
#include "jetbot_rl/env/env_view.h"
#include "jetbot_rl/env/randomization.h"
#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/robot/dof_limits.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/scene/curriculum.h"
#include "jetbot_rl/sensors/laser_scanner.h"
#include "jetbot_rl/tasks/task.h"
#include "jetbot_rl/tasks/velocity_task.h"
#include "jetbot_rl/world/world_model.h"

namespace jetbot_rl {

struct ActionLayout;
class EnvPhysics;
class EnvRandomizer;
class EnvScene;
class CameraSensor;
struct CameraSpec;
class EnvSensor;
struct SensedEnv;
class MoverSet;
class PhysicsModel;
class ScanSensor;
class ThreadPool;
class WorldDrawing;
struct WorkerContext;

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

  /// Rows of the batch: num_envs x robots_per_env (each robot an agent; docs/team.md).
  int numEnvs() const { return config_.numRows(); }
  int obsDim() const { return obs_dim_; }
  int actionDim() const;
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
  const std::vector<float>& actionLow() const;
  const std::vector<float>& actionHigh() const;
  /// Limits of every dof in action order, and whether each came from the URDF or a parameter.
  const std::vector<DofLimits>& dofLimits() const { return dof_limits_; }
  /// Every revolute and continuous joint of the robot, driven or not, root to leaves.
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  /// Number of envs reset because they diverged, since construction.
  std::uint64_t divergedCount() const { return diverged_count_; }
  /// Read-only view of env `env` (its root state, links, joints, layout, scan, ...);
  /// InputError when out of range.
  EnvView view(int env) const;
  /// Overwrites env `env`'s root pose and velocity (for tests and tools); InputError when invalid.
  void setRootState(int env, const RootState& state);

  /// The world every env shares (map, walls, region); nullptr when none is configured.
  const WorldModel* world() const;
  /// Obstacles left out since construction because they did not fit (world/placement_tries,
  /// world/max_generated_obstacles).
  std::uint64_t obstaclesGivenUp() const;
  /// Resets since construction whose generated layout could not be made (EnvLayout::unmade).
  std::uint64_t layoutsUnmade() const;
  /// The movers of every env (movers/...), or nullptr when there are none.
  const MoverSet* movers() const;
  /// Movers left out since construction because they did not fit (world/placement_tries).
  std::uint64_t moversGivenUp() const;
  /// Env `env`'s curriculum level: its generated layouts are drawn at it (below it with
  /// world/curriculum_mix).
  double difficulty(int env) const;
  /// The scanner in use, or nullptr.
  const ScannerSpec* scanner() const;
  /// The robot's camera `index`, or nullptr (none of that index): camera 0 is the one whose
  /// images the batch carries (state().images); every camera's: view().
  const CameraSpec* camera(int index = 0) const;
  /// The robot's cameras (docs/camera.md).
  int numCameras() const { return static_cast<int>(cameras_.size()); }

 private:
  friend class EnvView;

  void checkEnv(int env) const;
  /// Steps env `env` with the stepping thread's scratch: stepPhysics, sensePhysics, finishStep.
  void stepEnv(int env, WorkerContext& context);
  /// Steps the robots of env `group` (robots_per_env): all their physics, then all their
  /// sensors, then each one's end of step (batched_env_team.cpp).
  void stepTeam(int group, WorkerContext& context);
  /// The control step's physics of row `env` and what it touched.
  void stepPhysics(int env, WorkerContext& context);
  /// Its sensors after the physics.
  void sensePhysics(int env);
  /// Dones, rewards, the reset of an ended episode, observations (Isaac Lab's order).
  void finishStep(int env);
  /// Observes row `env` where it is now (with observation noise when configured).
  void observeRow(int env);
  /// Rounds: a waiting row's step (reward 0, no end, its observation kept).
  void holdRow(int env);
  /// The camera keeps each ended episode's last images for StepResult::final_images.
  bool keepsFinalImages() const;
  /// Rounds: ends the waiting rows' stand-in episodes (outcome kWaited) and starts all the
  /// robots of env `group` anew, together.
  void startRound(int group);
  void resetEnv(int env);
  /// Gives the task env `env`'s senses (scan, contact, last action).
  void senseEnv(int env);

  RobotModelConstPtr robot_;
  EnvConfig config_;
  std::unique_ptr<Task> task_;
  WorldDrawing* drawer_ = nullptr;  // the task, when it draws into the world
  int obs_dim_ = 0;
  std::unique_ptr<PhysicsModel> physics_;
  std::unique_ptr<EnvRandomizer> randomizer_;
  std::unique_ptr<ThreadPool> pool_;
  std::vector<std::unique_ptr<WorkerContext>> contexts_;  // per worker
  std::vector<std::unique_ptr<EnvPhysics>> envs_;
  std::unique_ptr<EnvScene> scene_;  // world, layouts, curriculum, people, other robots
  std::unique_ptr<ActionLayout> actions_layout_;  // bounds, names, twist kinematics
  std::vector<float> wheel_low_, wheel_high_;     // per dof: its velocity limits
  std::vector<float> actions_;                    // per env: its last action (zeros after a reset)
  std::vector<std::uint8_t> outcome_;             // per env: how its ended episode ended
  std::vector<DofLimits> dof_limits_;
  std::vector<std::string> joint_names_;
  std::vector<int> dof_of_joint_;      // per jointNames() entry: its dof, or -1
  std::vector<float> targets_;         // clamped (raw with action noise) actions of the step
  std::vector<std::uint8_t> ended_;    // per env: ended in the current step
  std::vector<float> final_scratch_;   // per env final observation slot
  std::vector<std::string> diverged_;  // per env divergence reason of the current step
  StepResult result_;
  std::uint64_t diverged_count_ = 0;
  std::vector<std::uint8_t> collided_;  // per env: in the last step, kHitWorld or kHitMover
  static constexpr std::uint8_t kHitWorld = 1, kHitMover = 2, kHitRobot = 3;
  // The sensors (the scanner and the camera, when the robot has them).
  std::unique_ptr<ScanSensor> scan_;
  SpeedLimitSpec speed_limit_spec_;          // speed_limit/...: the path ahead in the scan's frame
  std::unique_ptr<SpeedLimit> speed_limit_;  // none without speed_limit/enabled
  std::vector<float> speed_caps_;            // per env: its fastest forward v this step [m/s]
  std::vector<std::unique_ptr<CameraSensor>> cameras_;  // cameras_[0] fills result_.images
  std::vector<EnvSensor*> sensors_;                     // every sensor, in stepping order
};

}  // namespace jetbot_rl
