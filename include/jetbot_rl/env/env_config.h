#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/config/config_fields.h"
#include "jetbot_rl/env/randomization.h"
#include "jetbot_rl/planning/speed_limit.h"
#include "jetbot_rl/robot/motor_model.h"
#include "jetbot_rl/scene/mover_config.h"
#include "jetbot_rl/scene/team_config.h"
#include "jetbot_rl/sensors/camera_config.h"
#include "jetbot_rl/sensors/scanner_config.h"
#include "jetbot_rl/world/world_config.h"

namespace jetbot_rl {

/// How a wheel's drive follows its velocity target.
enum class DriveMode {
  kAuto,     ///< kVelocityLoop for a robot whose description has a Gazebo diff drive plugin.
  kDamping,  ///< Isaac Lab's velocity drive: torque drive_gain x error, up to the effort limit.
  /// A velocity servo as Gazebo's diff drive plugin or diff_drive_controller on a real base: up
  /// to the effort limit, with integral action, so that it holds the target in steady state.
  kVelocityLoop,
};

inline const EnumNameList<DriveMode>& enumNames(DriveMode) {
  static const EnumNameList<DriveMode> names{{DriveMode::kAuto, "auto"},
                                             {DriveMode::kDamping, "damping"},
                                             {DriveMode::kVelocityLoop, "velocity_loop"}};
  return names;
}

/// What an action is.
enum class ActionSpace {
  kWheels,  ///< A velocity target per dof [rad/s].
  kTwist,   ///< (v [m/s], omega [rad/s]) of a differential drive, as a base's cmd_vel takes.
};

inline const EnumNameList<ActionSpace>& enumNames(ActionSpace) {
  static const EnumNameList<ActionSpace> names{{ActionSpace::kWheels, "wheels"},
                                               {ActionSpace::kTwist, "twist"}};
  return names;
}

/// Configuration of a batch of environments; defaults are the Isaac Lab Jetbot seed's.
struct EnvConfig {
  int num_envs = 100;               ///< Number of environments in the batch.
  double env_spacing = 4.0;         ///< Distance between env origins on the square grid [m].
  double physics_dt = 1.0 / 120.0;  ///< Physics step [s].
  int decimation = 2;               ///< Physics steps per control step.
  double episode_length_s = 5.0;    ///< Episode length [s].
  /// Driven joints in action order; empty: the Gazebo diff drive plugin's [leftJoint,
  /// rightJoint], else [left_wheel_joint, right_wheel_joint] (resolvedDofNames()).
  std::vector<std::string> dof_names;
  std::uint64_t seed = 0;                           ///< Seed of the per-env random streams.
  int num_threads = 0;                              ///< Worker threads; 0 means all cores.
  double drive_gain = 10.0;                         ///< Velocity drive gain [N m s/rad].
  DriveMode drive = DriveMode::kAuto;               ///< How the wheels follow their targets.
  ActionSpace action_space = ActionSpace::kWheels;  ///< What an action is.
  /// A twist action's fastest backwards v [m/s]; -1: as fast as forwards (the wheels' limit).
  double twist_reverse_speed = -1.0;
  double effort_limit = 0.0;   ///< Drive torque limit [N m]; 0 takes the URDF <limit effort>.
  int solver_iterations = 10;  ///< Bullet constraint solver iterations per physics step.
  /// Wheel (dof) velocity limit [rad/s] for every dof; 0 takes the URDF <limit velocity>.
  double wheel_velocity_limit = 0.0;
  /// Coulomb friction coefficient with the ground of every body no dof drives (chassis, caster).
  double caster_friction = 0.0;
  /// Wheel radius for DiffDrive [m]; 0 derives it from the wheels' collision shapes.
  double wheel_radius = 0.0;
  /// Distance between the two wheels for DiffDrive [m]; 0 derives it from the dof joints.
  double wheel_separation = 0.0;
  /// Domain randomisation (off by default).
  RandomizationConfig randomization;
  /// Open-loop motor model between the targets and the wheels' drives (off by default).
  MotorModelConfig motor;
  /// Each env's world: map, walls, random obstacles (none by default).
  WorldConfig world;
  /// Moving obstacles in each env's world (none by default).
  MoverConfig movers;
  /// The laser scanner (the robot description's Gazebo ray sensor, if it has one).
  ScannerConfig scan;
  /// The camera (the robot description's Gazebo camera block, if it has one).
  CameraConfig camera;
  /// Robots per env (one by default).
  TeamConfig team;
  /// The forward speed limit near what the scan sees ahead (off by default).
  SpeedLimitConfig speed_limit;

  /// Throws ConfigError naming the first invalid field and its value.
  void validate() const;
  /// Control step = physics_dt * decimation [s].
  double controlDt() const { return physics_dt * decimation; }
  /// ceil(episode_length_s / controlDt()), as Isaac Lab computes it.
  int maxEpisodeLength() const;
  /// Thread count after resolving 0 to the number of cores.
  int resolvedThreads() const;
  /// Rows of the batch: num_envs x robots_per_env.
  int numRows() const { return num_envs * team.robots_per_env; }
};

class RobotModel;
/// dof_names, or when it is empty the robot's Gazebo diff drive plugin's wheel joints, else
/// [left_wheel_joint, right_wheel_joint].
std::vector<std::string> resolvedDofNames(const EnvConfig& config, const RobotModel& robot);

/// The fields of EnvConfig with their rules (see config_fields.h).
template <typename C, typename V>
IfConfig<C, EnvConfig> visitFields(C& c, V&& v) {
  v("num_envs", c.num_envs, inRange(1, 1000000), "Environments in the batch.");
  v("env_spacing", c.env_spacing, positiveUpTo(1000.0, "m"),
    "Distance between env origins on the square grid.");
  v("physics_dt", c.physics_dt, positiveUpTo(0.1, "s"), "Physics step (1/120 s).");
  v("decimation", c.decimation, inRange(1, 1000),
    "Physics steps per control step; control step = physics_dt x decimation.");
  v("episode_length_s", c.episode_length_s, positive("s"),
    "Episode length; max_episode_length = ceil(episode_length_s / control step), 2 to 1e9.");
  v("dof_names", c.dof_names, NameList{"", true},
    "Driven joints of robot_description, in action order; []: the Gazebo diff drive plugin's "
    "[leftJoint, rightJoint], else [left_wheel_joint, right_wheel_joint].");
  v("seed", c.seed, atLeast<std::uint64_t>(0), "Seed of the per-env random streams.");
  v("num_threads", c.num_threads, inRange(0, 1024, "", "0: all cores"), "Stepping threads.");
  v("drive_gain", c.drive_gain, positive("N m s/rad"), "Wheel velocity drive gain.");
  v("drive", c.drive, AnyValue{},
    "damping: Isaac Lab's velocity drive (torque drive_gain x error up to the effort limit; the "
    "Jetbot's); velocity_loop: a servo with integral action that holds the target in steady "
    "state within the effort limit (Gazebo's diff drive plugin, diff_drive_controller); auto: "
    "velocity_loop for a robot description with a Gazebo diff drive plugin, else damping.");
  v("action_space", c.action_space, AnyValue{},
    "wheels: a velocity target per dof [rad/s]; twist: (v [m/s], omega [rad/s]) of the "
    "differential drive (DiffDrive: wheel_radius, wheel_separation), bounded by the wheels' "
    "limits, as a base's cmd_vel.");
  v("twist_reverse_speed", c.twist_reverse_speed,
    atLeast(-1.0, "m/s", "-1: as fast as forwards; else >= 0"),
    "With action_space twist: the fastest backwards v, the action's lower bound -this (0: never "
    "backwards, as move_base's local planners default to with min_vel_x 0); -1: the fastest "
    "straight v the wheels allow, as forwards.");
  v("effort_limit", c.effort_limit, atLeast(0.0, "N m", "0: the URDF effort limit"),
    "Wheel drive torque limit.");
  v("solver_iterations", c.solver_iterations, inRange(1, 1000),
    "Bullet constraint solver iterations per physics step.");
  v("wheel_velocity_limit", c.wheel_velocity_limit,
    atLeast(0.0, "rad/s", "0: the URDF <limit velocity>"),
    "Wheel velocity limit of every dof: wheel targets are clamped to +-this.");
  v("caster_friction", c.caster_friction, atLeast(0.0),
    "Friction coefficient with the ground of every body no dof drives (chassis, caster).");
  v("wheel_radius", c.wheel_radius, atLeast(0.0, "m", "0: derived from the URDF"),
    "Wheel radius of the cmd_vel kinematics (DiffDrive).");
  v("wheel_separation", c.wheel_separation, atLeast(0.0, "m", "0: derived from the URDF"),
    "Distance between the two wheels of the cmd_vel kinematics (DiffDrive).");
  visitFields(c.randomization, v);
  visitFields(c.motor, v);
  visitFields(c.world, v);
  visitFields(c.movers, v);
  visitFields(c.scan, v);
  visitFields(c.camera, v);
  visitFields(c.team, v);
  visitFields(c.speed_limit, v);
}

/// The rules between EnvConfig's fields: an episode lasts 2 to 1e9 control steps; the world's and
/// the scanner's.
void checkFieldRules(const EnvConfig& config);

}  // namespace jetbot_rl
