#include "jetbot_rl/ros/deploy/deploy_node.h"

#include <ros/ros.h>

#include <filesystem>
#include <memory>
#include <sstream>

#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/robot_description.h"
#include "jetbot_rl/ros/common/stop_signal.h"
#include "jetbot_rl/ros/deploy/deploy_driver.h"

namespace jetbot_rl {
namespace {

/// Wheel targets -> Twist kinematics: the parameters (the checkpoint's where not given); where
/// neither has them, robot_description's.
/// `limits`: the policy's wheel velocity bounds [rad/s].
DiffDrive makeKinematics(const ros::NodeHandle& nh, const DriverParams& p,
                         const std::vector<double>& limits) {
  if (p.wheel_radius > 0.0 && p.wheel_separation > 0.0) {
    return DiffDrive(p.wheel_radius, p.wheel_separation, {p.dof_names.at(0), 0, 1.0, limits.at(0)},
                     {p.dof_names.at(1), 1, 1.0, limits.at(1)});
  }
  if (!nh.hasParam("robot_description")) {
    throwInvalid(p.wheel_radius > 0.0 ? "wheel_separation" : "wheel_radius", 0.0,
                 "0 takes the checkpoint's, which has none (its robot is no differential "
                 "drive), else robot_description's, which is not set");
  }
  return DiffDrive::fromRobot(*loadRobotDescription(nh), p.dof_names, limits, p.wheel_radius,
                              p.wheel_separation);
}

}  // namespace

int runDeployNode() {
  const std::atomic<bool>& stop = installStopSignalHandlers();
  ros::NodeHandle nh, pnh("~");
  const int code = runDeploy(nh, pnh, stop);
  ros::shutdown();
  return code;
}

int runDeploy(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::atomic<bool>& stop) {
  ppo::setTorchThreads(1);
  const std::optional<DeployParams> params = loadParams<DeployParams>(pnh, [](DeployParams& p) {
    std::string& checkpoint = p.driver.checkpoint;
    if (std::filesystem::is_directory(checkpoint)) {
      checkpoint = (std::filesystem::path(checkpoint) / "checkpoints/best.pt").string();
    }
  });
  if (!params) return 1;
  DeployParams p = *params;
  const std::string& checkpoint = p.driver.checkpoint;
  std::unique_ptr<ppo::Policy> policy;
  try {
    policy = std::make_unique<ppo::Policy>(checkpoint);
    ppo::requireObservationContract(policy->meta(), checkpoint);
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  const BatchSpec& trained = policy->meta().spec;
  std::unique_ptr<TaskObserver> observer;
  PolicyRun run;
  std::optional<DiffDrive> kinematics;
  try {
    if (!p.driver.task.empty() && p.driver.task != trained.task) {
      throwInvalid("task", "'" + p.driver.task + "'",
                   "the checkpoint was trained on task '" + trained.task + "'");
    }
    for (const std::string& line : takeTrainedSettings(p, trained.observer)) {
      ROS_WARN("%s: %s", pnh.getNamespace().c_str(), line.c_str());
    }
    // The baseline drives at the policy's top speed (as in the navigation benchmark) unless told.
    if (p.local.planner == LocalPlanner::kDwa && !pnh.hasParam("dwa/max_vel_x") &&
        topSpeed(trained) > 0.0) {
      p.local.dwa.max_vel_x = topSpeed(trained);
      checkFieldRules(p.local.dwa);
    }
    run = policyRunOf(*policy, checkpoint);
    observer = observerOf(trained, p.pursuit.xy_goal_tolerance, checkpoint);
    if (!run.twist) kinematics = makeKinematics(nh, p.driver, run.action_high);
  } catch (const ConfigError& e) {
    logParamError(pnh, e);
    return 1;
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  // Only the settings the task uses: goals and paths for a task with goals, wheels for wheel
  // actions.
  std::ostringstream in_use;
  if (observer->hasGoal()) {
    in_use << "xy_goal_tolerance " << p.pursuit.xy_goal_tolerance << " m, footprint_radius "
           << p.pursuit.footprint_radius << " m, path_clearance " << p.pursuit.path_clearance
           << " m, path_clearance_cost " << p.pursuit.path_clearance_cost
           << (kinematics ? ", " : "");
  }
  if (kinematics) {
    in_use << "wheel_radius " << p.driver.wheel_radius << " m, wheel_separation "
           << p.driver.wheel_separation << " m";
  }
  ROS_INFO("%s: settings in use (the checkpoint's unless given): %s", pnh.getNamespace().c_str(),
           in_use.str().empty() ? "none (no goals, twist actions)" : in_use.str().c_str());
  ROS_INFO("policy from iteration %lld (%lld env steps) of task %s",
           static_cast<long long>(policy->meta().iteration),
           static_cast<long long>(policy->meta().env_steps), policy->meta().spec.task.c_str());
  try {
    DeployDriver driver(nh, pnh, *policy, *observer, p, run, kinematics);
    ros::AsyncSpinner spinner(1);
    spinner.start();
    waitForStop(stop);
    spinner.stop();
    driver.stop();
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace jetbot_rl
