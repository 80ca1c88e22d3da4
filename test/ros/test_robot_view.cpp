// The robot view's logic without a master: cmd_vel through CmdVelMixer and EnvServer (realtime
// precedence over WheelTargets, time-out, lockstep and non-finite rejections), the tf tree, odom
// and joint_states contents, the parameters' rules and package:// resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ros/common/package_resolver.h"
#include "jetbot_rl/ros/env_node/cmd_vel_mixer.h"
#include "jetbot_rl/ros/env_node/env_server.h"
#include "jetbot_rl/ros/env_node/node_params.h"
#include "jetbot_rl/ros/env_node/robot_state_output.h"
#include "jetbot_rl/ros/env_node/tf_tree.h"

namespace jetbot_rl {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

std::unique_ptr<BatchedEnv> makeJetbots(int num_envs) {
  EnvConfig config;
  config.num_envs = num_envs;
  config.num_threads = 1;
  return std::make_unique<BatchedEnv>(RobotModel::fromUrdfFile(JETBOT_URDF), config);
}

geometry_msgs::Twist twist(double linear, double angular) {
  geometry_msgs::Twist t;
  t.linear.x = linear;
  t.angular.z = angular;
  return t;
}

WheelTargets wheels(std::vector<float> velocities) {
  WheelTargets msg;
  msg.velocities = std::move(velocities);
  return msg;
}

Eigen::Isometry3d toPose(const geometry_msgs::Transform& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() << t.translation.x, t.translation.y, t.translation.z;
  pose.linear() =
      Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).toRotationMatrix();
  return pose;
}

const geometry_msgs::TransformStamped& find(const std::vector<geometry_msgs::TransformStamped>& ts,
                                            const std::string& child) {
  for (const auto& t : ts) {
    if (t.child_frame_id == child) return t;
  }
  ADD_FAILURE() << "no transform to " << child;
  static const geometry_msgs::TransformStamped none;
  return none;
}

// ---- CmdVelMixer: the Jetbot's wheel radius 0.03 m, separation 0.1125 m, limit 20 rad/s ----

TEST(CmdVelMixer, ConvertsTwistsAndKeepsThePreviousCommandOnANonFiniteOne) {
  auto env = makeJetbots(2);
  CmdVelMixer mixer(DiffDrive::fromEnv(*env), 2, 0.5);
  const auto t0 = Clock::now();
  EXPECT_FALSE(mixer.anyFresh(t0));
  mixer.set(1, twist(0.3, 0.0), t0);  // straight: v / r on both wheels
  std::vector<float> targets{1, 2, 3, 4};
  mixer.apply(t0 + milliseconds(100), targets.data(), targets.size());
  EXPECT_EQ(targets[0], 1.0f);  // env 0 has no command: untouched
  EXPECT_EQ(targets[1], 2.0f);
  EXPECT_NEAR(targets[2], 10.0, 1e-5);
  EXPECT_NEAR(targets[3], 10.0, 1e-5);

  mixer.set(0, twist(0.0, 2.0), t0);  // in place: -/+ omega * separation / 2 / r
  mixer.apply(t0, targets.data(), targets.size());
  EXPECT_NEAR(targets[0], -3.75, 1e-5);
  EXPECT_NEAR(targets[1], 3.75, 1e-5);

  geometry_msgs::Twist bad = twist(0.3, 0.0);
  bad.linear.y = std::numeric_limits<double>::infinity();  // not driving, still rejected
  try {
    mixer.set(0, bad, t0 + milliseconds(200));
    FAIL() << "an infinite component was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("linear.y = inf is not finite"), std::string::npos)
        << e.what();
  }
  bad = twist(0.3, std::nan(""));
  EXPECT_THROW(mixer.set(0, bad, t0 + milliseconds(200)), InputError);
  targets = {0, 0, 0, 0};
  mixer.apply(t0 + milliseconds(400), targets.data(), targets.size());
  EXPECT_NEAR(targets[0], -3.75, 1e-5) << "the previous command did not stay";
  // ... with its own age: it expires 0.5 s after t0, not after the rejected message
  targets = {0, 0, 0, 0};
  mixer.apply(t0 + milliseconds(600), targets.data(), targets.size());
  EXPECT_EQ(targets, (std::vector<float>{0, 0, 0, 0}));
  EXPECT_FALSE(mixer.anyFresh(t0 + milliseconds(600)));
  EXPECT_THROW(mixer.set(2, twist(0, 0), t0), InputError);  // not a robot env
}

TEST(CmdVelMixer, BeyondTheWheelLimitBothWheelsScaleTogether) {
  auto env = makeJetbots(1);
  CmdVelMixer mixer(DiffDrive::fromEnv(*env), 1, 0.5);
  const auto t0 = Clock::now();
  mixer.set(0, twist(1.0, 4.0), t0);  // wants 25.8 and 40.8 rad/s
  std::vector<float> targets{0, 0};
  mixer.apply(t0, targets.data(), targets.size());
  EXPECT_NEAR(targets[1], 20.0, 1e-4);  // the faster wheel at the limit
  EXPECT_NEAR(targets[0], 20.0 * (1.0 - 0.225) / (1.0 + 0.225), 1e-4);
  // the curvature omega / v of the commanded twist is kept
  const PlanarTwist driven = mixer.drive().bodyTwist({targets[0], targets[1]});
  EXPECT_NEAR(driven.angular / driven.linear, 4.0, 1e-4);
}

// ---- EnvServer with cmd_vel ----

TEST(EnvServerCmdVel, LockstepRejectsAndCountsCmdVelAndChangesNothing) {
  auto env = makeJetbots(1);
  EnvServer server(*env, EnvMode::kLockstep, 0.5);
  server.enableCmdVel(DiffDrive::fromEnv(*env), 1, 0.5);
  const EnvStep::ConstPtr before = server.state();
  EXPECT_FALSE(server.onCmdVel(0, twist(0.3, 0.0), Clock::now()));
  EXPECT_FALSE(server.onCmdVel(0, twist(0.3, 0.0), Clock::now()));
  EXPECT_EQ(server.counters().cmd_vel_rejections, 2u);
  EXPECT_NE(server.counters().last_cmd_vel_rejection.find(
                "cmd_vel of env 0 rejected: lockstep mode steps only with WheelTargets"),
            std::string::npos)
      << server.counters().last_cmd_vel_rejection;
  EXPECT_EQ(server.counters().rejections, 0u);  // WheelTargets' count is separate
  EXPECT_EQ(server.state(), before);
  // lockstep still steps with WheelTargets only
  WheelTargets msg = wheels({5, 5});
  EXPECT_TRUE(server.onWheelTargets(msg, Clock::now()));
}

TEST(EnvServerCmdVel, RealtimeFreshCmdVelDrivesItsEnvOverWheelTargetsThenHandsBack) {
  auto env = makeJetbots(2);
  EnvServer server(*env, EnvMode::kRealtime, 0.5);
  server.enableCmdVel(DiffDrive::fromEnv(*env), 1, 0.3);  // env 0 only
  const auto t0 = Clock::now();
  server.onWheelTargets(wheels({5, 5, 5, 5}), t0);
  EXPECT_TRUE(server.onCmdVel(0, twist(-0.3, 0.0), t0));  // -10 rad/s on both wheels
  for (int k = 0; k < 30; ++k) server.onTick(t0 + milliseconds(k));
  EXPECT_NEAR(env->view(0).dofVelocity(0), -10.0, 1.0);  // env 0: cmd_vel wins
  EXPECT_NEAR(env->view(0).dofVelocity(1), -10.0, 1.0);
  EXPECT_NEAR(env->view(1).dofVelocity(0), 5.0, 0.5);  // env 1: WheelTargets
  EXPECT_NEAR(env->view(1).dofVelocity(1), 5.0, 0.5);

  // cmd_vel older than cmd_vel_timeout (0.3 s), WheelTargets still fresh (0.5 s): env 0 goes
  // back to WheelTargets
  for (int k = 0; k < 60; ++k) server.onTick(t0 + milliseconds(320 + k));
  EXPECT_NEAR(env->view(0).dofVelocity(0), 5.0, 0.5);

  // a fresh cmd_vel again, with no fresh WheelTargets: env 0 drives, env 1 brakes
  const auto t1 = t0 + milliseconds(1000);
  EXPECT_TRUE(server.onCmdVel(0, twist(0.0, 2.0), t1));  // -/+ 3.75 rad/s
  for (int k = 0; k < 60; ++k) server.onTick(t1 + milliseconds(k));
  EXPECT_NEAR(env->view(0).dofVelocity(0), -3.75, 0.4);
  EXPECT_NEAR(env->view(0).dofVelocity(1), 3.75, 0.4);
  EXPECT_LT(std::abs(env->view(1).dofVelocity(0)), 0.5);

  // ... and after cmd_vel_timeout without anything: every env brakes
  for (int k = 0; k < 60; ++k) server.onTick(t1 + milliseconds(400 + k));
  EXPECT_LT(std::abs(env->view(0).dofVelocity(0)), 0.5);
  EXPECT_LT(std::abs(env->view(0).dofVelocity(1)), 0.5);
  EXPECT_EQ(server.counters().cmd_vel_rejections, 0u);
}

TEST(EnvServerCmdVel, RealtimeNonFiniteCmdVelIsCountedAndThePreviousCommandStays) {
  auto env = makeJetbots(1);
  EnvServer server(*env, EnvMode::kRealtime, 0.5);
  server.enableCmdVel(DiffDrive::fromEnv(*env), 1, 0.5);
  const auto t0 = Clock::now();
  EXPECT_TRUE(server.onCmdVel(0, twist(0.3, 0.0), t0));
  for (int k = 0; k < 30; ++k) server.onTick(t0 + milliseconds(k));
  EXPECT_FALSE(server.onCmdVel(0, twist(std::nan(""), 0.0), t0 + milliseconds(30)));
  EXPECT_EQ(server.counters().cmd_vel_rejections, 1u);
  EXPECT_NE(server.counters().last_cmd_vel_rejection.find("linear.x = nan is not finite"),
            std::string::npos)
      << server.counters().last_cmd_vel_rejection;
  for (int k = 0; k < 30; ++k) server.onTick(t0 + milliseconds(31 + k));
  EXPECT_NEAR(env->view(0).dofVelocity(0), 10.0, 0.5) << "the previous command did not stay";

  // an invalid WheelTargets is still rejected as a whole while cmd_vel drives
  server.onWheelTargets(wheels({1, 2, 3}), t0 + milliseconds(70));
  server.onTick(t0 + milliseconds(71));
  EXPECT_EQ(server.counters().rejections, 1u);
  EXPECT_NE(server.counters().last_rejection.find("expected 2 values"), std::string::npos)
      << server.counters().last_rejection;
  EXPECT_EQ(server.state()->step, 61u);  // the tick stepped with the previous targets
}

TEST(EnvServerCmdVel, WithoutRobotEnvsCmdVelIsRejected) {
  auto env = makeJetbots(1);
  EnvServer server(*env, EnvMode::kRealtime, 0.5);
  EXPECT_FALSE(server.onCmdVel(0, twist(0.1, 0.0), Clock::now()));
  EXPECT_NE(server.counters().last_cmd_vel_rejection.find("robot_view_envs 0"), std::string::npos);
}

// ---- parameters ----

TEST(RobotViewParams, DroppingThePrefixNeedsExactlyOneRobotEnv) {
  NodeParams p;
  p.setup.env.num_envs = 4;
  p.robot_view_envs = 2;
  validateConfig(p);
  EXPECT_EQ(robotViewEnvs(p), 2);
  EXPECT_EQ(tfEnvs(p), 4);  // tf_envs 4
  p.env_prefix = false;
  try {
    validateConfig(p);
    FAIL() << "env_prefix false with 2 robot envs was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("invalid env_prefix = false"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("robot_view_envs 1, got 2"), std::string::npos)
        << e.what();
  }
  p.robot_view_envs = 0;
  EXPECT_THROW(validateConfig(p), ConfigError);
  p.robot_view_envs = 5;  // clamped to num_envs 1
  p.setup.env.num_envs = 1;
  validateConfig(p);
  EXPECT_EQ(robotViewEnvs(p), 1);
  p.tf_envs = 0;
  EXPECT_EQ(tfEnvs(p), 1);  // robot envs always get tf
  p.odom_rate = 0.0;
  EXPECT_THROW(validateConfig(p), ConfigError);
  p.odom_rate = 50.0;
  p.cmd_vel_timeout = -1.0;
  EXPECT_THROW(validateConfig(p), ConfigError);
}

// ---- the tf tree, odom and joint_states ----

TEST(TfTree, OneTreePerEnvFromWorldThroughOdomAndTheRootToEveryLink) {
  auto env = makeJetbots(3);
  std::vector<float> turning{-5, 8, -5, 8, -5, 8};
  for (int s = 0; s < 40; ++s) env->step(turning);
  TfTree tree(*env, 2, RobotNames(true), true);
  tree.update(*env, ros::Time(1.5));
  ASSERT_EQ(tree.statics().size(), 2u);
  EXPECT_EQ(tree.statics()[1].header.frame_id, "world");
  EXPECT_EQ(tree.statics()[1].child_frame_id, "env_1/odom");
  EXPECT_NEAR(tree.statics()[1].transform.translation.x, env->view(1).origin().x(), 1e-12);
  EXPECT_NEAR(tree.statics()[1].transform.translation.y, env->view(1).origin().y(), 1e-12);
  ASSERT_EQ(tree.transforms().size(), 8u);  // 2 envs x 4 links

  const auto& ts = tree.transforms();
  EXPECT_EQ(find(ts, "env_1/base_link").header.frame_id, "env_1/odom");
  EXPECT_EQ(find(ts, "env_1/caster_link").header.frame_id, "env_1/base_link");
  EXPECT_EQ(find(ts, "env_1/left_wheel").header.frame_id, "env_1/base_link");
  EXPECT_EQ(find(ts, "env_1/right_wheel").header.frame_id, "env_1/base_link");
  EXPECT_EQ(find(ts, "env_1/left_wheel").header.stamp, ros::Time(1.5));

  // world -> odom -> base_link -> wheel is the wheel's simulated pose
  const Eigen::Isometry3d world_odom = toPose(tree.statics()[1].transform);
  const Eigen::Isometry3d odom_base = toPose(find(ts, "env_1/base_link").transform);
  for (const LinkPose& link : env->view(1).linkPoses()) {
    const Eigen::Isometry3d composed =
        link.link == "base_link"
            ? world_odom * odom_base
            : world_odom * odom_base * toPose(find(ts, "env_1/" + link.link).transform);
    // Bullet works in single precision: equal to its rounding (1e-7)
    EXPECT_LT((composed.matrix() - link.pose.matrix()).cwiseAbs().maxCoeff(), 1e-6) << link.link;
  }
  // odom -> base_link is the odometry's pose
  const RootState root = env->view(1).rootState();
  EXPECT_LT((odom_base.translation() - root.position).norm(), 1e-7);
  EXPECT_LT(Eigen::Quaterniond(odom_base.rotation()).angularDistance(root.orientation), 1e-6);
}

TEST(TfTree, UnprefixedWithoutLinksLeavesTheLinksToRobotStatePublisher) {
  auto env = makeJetbots(1);
  TfTree tree(*env, 1, RobotNames(false), false);
  ASSERT_EQ(tree.statics().size(), 1u);
  EXPECT_EQ(tree.statics()[0].child_frame_id, "odom");
  ASSERT_EQ(tree.transforms().size(), 1u);
  EXPECT_EQ(tree.transforms()[0].header.frame_id, "odom");
  EXPECT_EQ(tree.transforms()[0].child_frame_id, "base_link");
  EXPECT_EQ(TfTree(*env, 0, RobotNames(true), true).transforms().size(), 0u);
}

TEST(TfTree, TribotLinksHangFromTheirUrdfParents) {
  EnvConfig config;
  config.num_envs = 1;
  config.num_threads = 1;
  config.dof_names = {"wheel_left_joint", "wheel_right_joint"};
  config.wheel_velocity_limit = 8.0;
  config.effort_limit = 0.3;
  BatchedEnv env(RobotModel::fromUrdfFile(TRIBOT_URDF, packageResolver()), config);
  TfTree tree(env, 1, RobotNames(false), true);
  const auto& ts = tree.transforms();
  EXPECT_EQ(find(ts, "base_footprint").header.frame_id, "odom");
  EXPECT_EQ(find(ts, "base_link").header.frame_id, "base_footprint");
  EXPECT_EQ(find(ts, "caster_back_link").header.frame_id, "base_link");
  EXPECT_EQ(find(ts, "wheel_left_link").header.frame_id, "base_link");
  tree.update(env, ros::Time(0.1));
  // the URDF joint: base_link -> wheel_left_link at (0, 0.08, 0.023), rolled by -1.57 rad
  const auto& wheel = find(ts, "wheel_left_link").transform;
  EXPECT_NEAR(wheel.translation.y, 0.08, 1e-6);
  EXPECT_NEAR(wheel.translation.z, 0.023, 1e-6);
  EXPECT_NEAR(find(ts, "base_link").transform.translation.z, 0.010, 1e-9);
}

TEST(RobotState, OdometryAndJointStatesOfTheSimulatedState) {
  auto env = makeJetbots(2);
  for (int s = 0; s < 90; ++s) env->step({0, 0, 10, 10});  // env 1 drives straight, 0.3 m/s
  nav_msgs::Odometry odom = odometryFrame(*env, 1, RobotNames(true));
  EXPECT_EQ(odom.header.frame_id, "env_1/odom");
  EXPECT_EQ(odom.child_frame_id, "env_1/base_link");
  updateOdometry(*env, 1, ros::Time(1.5), odom);
  EXPECT_EQ(odom.header.stamp, ros::Time(1.5));
  const RootState root = env->view(1).rootState();
  EXPECT_NEAR(odom.pose.pose.position.x, root.position.x(), 1e-12);
  EXPECT_GT(odom.pose.pose.position.x, 0.3);  // in the env's frame, not the world's
  EXPECT_LT(odom.pose.pose.position.x, 0.5);
  EXPECT_NEAR(odom.pose.pose.orientation.w, root.orientation.w(), 1e-12);
  EXPECT_NEAR(odom.twist.twist.linear.x, 0.3, 0.015);  // in the base frame, within 5 %
  EXPECT_NEAR(odom.twist.twist.linear.y, 0.0, 0.01);
  EXPECT_NEAR(odom.twist.twist.angular.z, 0.0, 0.05);
  for (int i = 0; i < 36; ++i) {
    EXPECT_EQ(odom.pose.covariance[i], i % 7 == 0 ? kOdomVariance : 0.0) << i;
    EXPECT_EQ(odom.twist.covariance[i], i % 7 == 0 ? kOdomVariance : 0.0) << i;
  }

  sensor_msgs::JointState state;
  JointStates scratch;
  updateJointState(*env, 1, ros::Time(1.5), scratch, state);
  EXPECT_EQ(state.name, (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
  ASSERT_EQ(state.velocity.size(), 2u);
  EXPECT_NEAR(state.velocity[0], env->view(1).dofVelocity(0), 1e-12);
  EXPECT_NEAR(state.velocity[1], 10.0, 0.5);
  EXPECT_GT(state.position[0], 10.0);  // about 14 rad in 1.5 s
  EXPECT_EQ(state.effort.size(), 2u);
  EXPECT_EQ(state.header.stamp, ros::Time(1.5));
  updateJointState(*env, 0, ros::Time(1.5), scratch, state);
  EXPECT_NEAR(state.velocity[0], 0.0, 0.05);
}

// ---- package:// ----

TEST(PackageResolver, ResolvesPackageUrisAndNamesWhatItCannot) {
  const std::string path =
      resolvePackageUri("package://jetbot_rl/urdf/examples/meshes/chassis.stl");
  EXPECT_TRUE(std::ifstream(path).good()) << path;
  try {
    resolvePackageUri("package://no_such_package_here/mesh.stl");
    FAIL() << "an unknown package resolved";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("package 'no_such_package_here'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(resolvePackageUri("http://example.com/mesh.stl"), Error);
  // through the core: an unresolvable mesh names the link and the URI
  std::ifstream file(TRIBOT_URDF);
  std::stringstream text;
  text << file.rdbuf();
  std::string urdf = text.str();
  const std::string from = "package://jetbot_rl/urdf/examples/meshes/chassis.stl";
  urdf.replace(urdf.find(from, urdf.find("<collision>")), from.size(),
               "package://no_such_package_here/chassis.stl");
  try {
    RobotModel::fromUrdfString(urdf, packageResolver());
    FAIL() << "an unresolvable mesh loaded";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("base_link"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("package://no_such_package_here/chassis.stl"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace jetbot_rl
