#include "jetbot_rl/ros/deploy/deploy_node.h"

#include <ros/ros.h>
#include <torch/utils.h>

#include <filesystem>
#include <memory>

#include "jetbot_rl/ppo/policy.h"
#include "jetbot_rl/robot/diff_drive.h"
#include "jetbot_rl/ros/common/param_reader.h"
#include "jetbot_rl/ros/common/robot_description.h"
#include "jetbot_rl/ros/common/stop_signal.h"
#include "jetbot_rl/ros/deploy/deploy_driver.h"
#include "jetbot_rl/ros/deploy/goal_pursuit.h"
#include "jetbot_rl/tasks/task_factory.h"

namespace jetbot_rl {
namespace {

/// Wheel targets -> Twist kinematics: the parameters; one given as 0 from robot_description.
/// `limits`: the policy's wheel velocity bounds [rad/s].
DiffDrive makeKinematics(const ros::NodeHandle& nh, const DriverParams& p,
                         const std::vector<double>& limits) {
  if (p.wheel_radius > 0.0 && p.wheel_separation > 0.0) {
    return DiffDrive(p.wheel_radius, p.wheel_separation, {p.dof_names.at(0), 0, 1.0, limits.at(0)},
                     {p.dof_names.at(1), 1, 1.0, limits.at(1)});
  }
  if (!nh.hasParam("robot_description")) {
    throwInvalid(p.wheel_radius > 0.0 ? "wheel_separation" : "wheel_radius", 0.0,
                 "0 takes it from robot_description, which is not set");
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
  torch::set_num_threads(1);
  const std::optional<DeployParams> params = loadParams<DeployParams>(pnh, [](DeployParams& p) {
    std::string& checkpoint = p.driver.checkpoint;
    if (std::filesystem::is_directory(checkpoint)) {
      checkpoint = (std::filesystem::path(checkpoint) / "checkpoints/best.pt").string();
    }
  });
  if (!params) return 1;
  const DriverParams& driver_params = params->driver;
  std::unique_ptr<ppo::Policy> policy;
  try {
    policy = std::make_unique<ppo::Policy>(driver_params.checkpoint);
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  std::unique_ptr<TaskObserver> observer;
  PolicyRun run;
  ScanBeams beams;
  std::optional<DiffDrive> kinematics;
  double footprint_radius = params->pursuit.footprint_radius;
  try {
    run = policyRunOf(*policy, driver_params.checkpoint);
    if (observesScan(policy->meta().spec.task)) {
      beams = scanBeamsOf(policy->meta().spec, driver_params, driver_params.checkpoint);
    }
    const std::string& trained_task = policy->meta().spec.task;
    if (!driver_params.task.empty() && driver_params.task != trained_task) {
      throwInvalid("task", "'" + driver_params.task + "'",
                   "the checkpoint was trained on task '" + trained_task + "'");
    }
    observer = observerOf(policy->meta().spec, beams, params->pursuit.xy_goal_tolerance,
                          driver_params.checkpoint);
    if (!run.twist) kinematics = makeKinematics(nh, driver_params, run.action_high);
    const bool plans =
        observer->hasGoal() && GoalPursuit::plansPaths(params->pursuit, run.path_lookahead);
    if (plans && footprint_radius == 0.0) {
      if (!nh.hasParam("robot_description")) {
        throwInvalid("footprint_radius", 0.0,
                     "0 takes it from robot_description, which is not set (paths on the map are "
                     "planned for the robot's footprint)");
      }
      footprint_radius = loadRobotDescription(nh)->footprintRadius();
    }
  } catch (const ConfigError& e) {
    logParamError(pnh, e);
    return 1;
  } catch (const Error& e) {
    ROS_FATAL("%s: %s", pnh.getNamespace().c_str(), e.what());
    return 1;
  }
  ROS_INFO("policy from iteration %lld (%lld env steps) of task %s",
           static_cast<long long>(policy->meta().iteration),
           static_cast<long long>(policy->meta().env_steps), policy->meta().spec.task.c_str());
  try {
    DeployDriver driver(nh, pnh, *policy, *observer, *params, run, beams, kinematics,
                        footprint_radius);
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
