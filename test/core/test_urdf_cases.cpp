// URDFs as robot makers publish them: no <limit>, a massless root, rotated wheel frames, mesh
// collisions, caster friction; and the joint and root-twist accessors the ROS adapter reads.
#include <cmath>
#include <functional>

#include "jetbot_rl/errors.h"
#include "robot/physics_model.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using namespace test;

/// Expects `f` to throw ModelError whose message holds every one of `parts`.
void expectModelError(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no ModelError; expected one naming " << parts.front();
  } catch (const ModelError& e) {
    for (const auto& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  }
}

const std::string kChassisCollision =
    "<geometry><mesh filename=\"package://jetbot_rl/urdf/examples/meshes/chassis.stl\" "
    "scale=\"0.001 0.001 0.001\"/></geometry>\n    </collision>";

/// The tribot with its chassis collision mesh given by `filename` instead.
std::string tribotWithChassis(const std::string& filename) {
  return replaceOnce(tribotUrdfText(), kChassisCollision,
                     "<geometry><mesh filename=\"" + filename +
                         "\" scale=\"0.001 0.001 0.001\"/></geometry>\n    </collision>");
}

// ---- Wheel joints without <limit> ----

TEST(UrdfCases, NoLimitNeedsTheVelocityParameter) {
  EnvConfig config = tribotConfig(1);
  config.wheel_velocity_limit = 0.0;
  expectModelError([&] { BatchedEnv env(tribot(), config); },
                   {"joint 'wheel_left_joint': needs <limit velocity>", "wheel_velocity_limit"});
}

TEST(UrdfCases, NoLimitNeedsTheEffortParameter) {
  // Without its Gazebo diff drive plugin (whose wheelTorque would give it), and without the
  // parameter.
  std::string urdf = tribotUrdfText();
  const auto from = urdf.find("  <gazebo>\n    <plugin name=\"tribot_diff_drive\"");
  const auto to = urdf.find("</gazebo>", from);
  ASSERT_NE(from, std::string::npos);
  urdf.erase(from, to + std::string("</gazebo>").size() - from);
  EnvConfig config = tribotConfig(1);
  config.effort_limit = 0.0;
  expectModelError([&] { BatchedEnv env(RobotModel::fromUrdfString(urdf, testResolver), config); },
                   {"joint 'wheel_left_joint': needs <limit effort>", "effort_limit"});
}

TEST(UrdfCases, NoLimitLoadsWithParameters) {
  BatchedEnv env(tribot(), tribotConfig(1));
  ASSERT_EQ(env.dofLimits().size(), 2u);
  for (const DofLimits& d : env.dofLimits()) {
    EXPECT_EQ(d.velocity_limit, 8.0);
    EXPECT_EQ(d.velocity_source, LimitSource::kParameter);
    EXPECT_EQ(d.urdf_velocity_limit, 0.0);
    EXPECT_EQ(d.effort_limit, 0.3);
    EXPECT_EQ(d.effort_source, LimitSource::kParameter);
  }
  EXPECT_EQ(env.actionHigh()[1], 8.0f);
  EXPECT_EQ(describeDofLimits(env.dofLimits()[0]),
            "wheel_left_joint: velocity limit 8 rad/s (wheel_velocity_limit; URDF: none), "
            "effort limit 0.3 N m (effort_limit; URDF: none)");
}

TEST(UrdfCases, JetbotLimitsComeFromTheUrdfUnlessAParameterWins) {
  BatchedEnv urdf_env(jetbot(), smallConfig(1));
  const DofLimits& d = urdf_env.dofLimits()[0];
  EXPECT_EQ(d.name, "left_wheel_joint");
  EXPECT_EQ(d.velocity_source, LimitSource::kUrdf);
  EXPECT_EQ(d.effort_source, LimitSource::kUrdf);
  EXPECT_EQ(describeDofLimits(d),
            "left_wheel_joint: velocity limit 20 rad/s (URDF), effort limit 0.08 N m (URDF)");

  EnvConfig config = smallConfig(1);
  config.wheel_velocity_limit = 15.0;
  BatchedEnv env(jetbot(), config);
  EXPECT_EQ(env.actionHigh()[0], 15.0f);
  EXPECT_EQ(env.actionLow()[1], -15.0f);
  EXPECT_EQ(env.dofLimits()[1].velocity_source, LimitSource::kParameter);
  EXPECT_EQ(describeDofLimits(env.dofLimits()[1]),
            "right_wheel_joint: velocity limit 15 rad/s (wheel_velocity_limit; URDF: 20 rad/s, "
            "overridden), effort limit 0.08 N m (URDF)");
}

// ---- A massless root ----

TEST(UrdfCases, MasslessRootIsMergedAndIsTheBaseFrame) {
  const auto model = tribot();
  ASSERT_EQ(model->bodies().size(), 3u);
  const BodyModel& base = model->bodies()[0];
  EXPECT_EQ(base.link_name, "base_footprint");
  ASSERT_EQ(base.links.size(), 4u);
  EXPECT_EQ(base.links[1].name, "base_link");
  EXPECT_EQ(base.links[2].name, "caster_back_link");
  EXPECT_EQ(base.links[3].name, "base_scan");
  EXPECT_EQ(base.links[3].parent, "base_link");
  // each link keeps its URDF parent (for tf): the tree, not the merged bodies
  EXPECT_EQ(base.links[0].parent, "");
  EXPECT_EQ(base.links[1].parent, "base_footprint");
  EXPECT_EQ(base.links[2].parent, "base_link");
  EXPECT_EQ(model->bodies()[1].links[0].parent, "base_link");
  EXPECT_NEAR(base.mass, 1.01, 1e-12);
  EXPECT_NEAR(base.links[1].offset.translation().z(), 0.010, 1e-12);
  // base_footprint is on the ground: the wheels and the caster reach down to it.
  EXPECT_NEAR(model->restHeight(), 0.0, 1e-5);

  BatchedEnv env(tribot(), tribotConfig(1));
  for (int s = 0; s < 60; ++s) env.step(uniformActions(env, 0.0f, 0.0f));
  const RootState root = env.view(0).rootState();
  EXPECT_NEAR(root.position.z(), 0.0, 1e-3);  // the root state is base_footprint's
  for (const LinkPose& link : env.view(0).linkPoses()) {
    if (link.link == "base_link") {
      EXPECT_NEAR((link.pose.translation() - env.view(0).origin()).z(), 0.010, 1e-3);
    }
  }
}

TEST(UrdfCases, AMasslessRootAloneIsStillAnError) {
  // The chassis on a moving joint: nothing with mass is fixed to the root.
  const std::string detached =
      replaceOnce(tribotUrdfText(), "<joint name=\"base_joint\" type=\"fixed\">",
                  "<joint name=\"base_joint\" type=\"continuous\">");
  expectModelError([&] { RobotModel::fromUrdfString(detached, testResolver); },
                   {"link 'base_footprint'", "no <inertial>"});
}

// ---- Rotated wheel joint frames ----

TEST(UrdfCases, RotatedWheelFramesKeepASingleRoundedTyre) {
  PhysicsModel physics(tribot(), tribotConfig(1));
  for (const std::string joint : {"wheel_left_joint", "wheel_right_joint"}) {
    const btCollisionShape* shape = physics.bodies()[tribot()->bodyOfJoint(joint)].shape;
    EXPECT_EQ(shape->getShapeType(), CYLINDER_SHAPE_PROXYTYPE) << joint;
    EXPECT_NEAR(shape->getMargin(), 0.009, 1e-9) << joint;  // rounded: half the tyre width
  }
}

/// Mean body-frame forward COM velocity over 60 steps after 60, driving both wheels at `target`.
double forwardSpeed(const RobotModelConstPtr& robot, float target) {
  BatchedEnv env(robot, tribotConfig(1));
  double sum = 0.0;
  for (int s = 0; s < 120; ++s) {
    env.step(uniformActions(env, target, target));
    if (s >= 60) sum += env.view(0).rootState().comLinearVelocityBody().x();
  }
  return sum / 60;
}

TEST(UrdfCases, PositiveTargetsDriveAlongTheUrdfAxis) {
  // axis 0 0 1 in a frame rotated by rpy -1.57 0 0 points left (+y): positive drives forward.
  EXPECT_NEAR(forwardSpeed(tribot(), 5.0f), 5.0 * 0.033, 0.05 * 5.0 * 0.033);
  // The same frames with axis 0 0 -1 point right: positive drives backward.
  std::string urdf = tribotUrdfText();
  for (int i = 0; i < 2; ++i) {
    urdf = replaceOnce(urdf, "<axis xyz=\"0 0 1\"/>", "<axis xyz=\"0 0 -1\"/>");
  }
  EXPECT_NEAR(forwardSpeed(RobotModel::fromUrdfString(urdf, testResolver), 5.0f), -5.0 * 0.033,
              0.05 * 5.0 * 0.033);
}

// ---- Mesh collisions ----

TEST(UrdfCases, StlChassisIsItsScaledConvexHull) {
  const BodyModel& base = tribot()->bodies()[0];
  ASSERT_EQ(base.collisions.size(), 2u);
  const CollisionGeometry& chassis = base.collisions[0];
  ASSERT_EQ(chassis.type, CollisionGeometry::Type::kMesh);
  EXPECT_EQ(chassis.mesh_uri, "package://jetbot_rl/urdf/examples/meshes/chassis.stl");
  EXPECT_EQ(chassis.vertices.size(), 16u);  // an octagonal prism: STL's repeats are joined
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low;
  for (const auto& v : chassis.vertices) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  EXPECT_TRUE(low.isApprox(Eigen::Vector3d(-0.100, -0.060, 0.015), 1e-9)) << low.transpose();
  EXPECT_TRUE(high.isApprox(Eigen::Vector3d(0.040, 0.060, 0.100), 1e-9)) << high.transpose();
  PhysicsModel physics(tribot(), tribotConfig(1));
  EXPECT_EQ(physics.bodies()[0].shape->getShapeType(), COMPOUND_SHAPE_PROXYTYPE);
}

TEST(UrdfCases, RestHeightCountsMeshVertices) {
  // Lower the chassis mesh 50 mm below base_link: it becomes the lowest point.
  const std::string urdf = replaceOnce(tribotUrdfText(),
                                       "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n"
                                       "      <geometry><mesh",
                                       "<collision>\n      <origin xyz=\"0 0 -0.05\" rpy=\"0 0 "
                                       "0\"/>\n      <geometry><mesh");
  const auto model = RobotModel::fromUrdfString(urdf, testResolver);
  EXPECT_NEAR(model->restHeight(), -(0.010 - 0.05 + 0.015), 1e-9);
}

TEST(UrdfCases, ALoneMeshStandsWhereItsVerticesAre) {
  // No caster: the chassis mesh, lowered to the ground, is the base body's only shape (placed in
  // its COM frame, 7 cm from base_footprint) and slides on its flat bottom.
  std::string urdf = replaceOnce(tribotUrdfText(),
                                 "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n"
                                 "      <geometry><box size=\"0.03 0.03 0.02\"/></geometry>\n"
                                 "    </collision>",
                                 "");
  urdf = replaceOnce(
      urdf, "<collision>\n      <origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <geometry><mesh",
      "<collision>\n      <origin xyz=\"0 0 -0.025\" rpy=\"0 0 0\"/>\n      "
      "<geometry><mesh");
  const auto model = RobotModel::fromUrdfString(urdf, testResolver);
  ASSERT_EQ(model->bodies()[0].collisions.size(), 1u);
  EXPECT_NEAR(model->restHeight(), 0.0, 1e-5);
  BatchedEnv env(model, tribotConfig(1));
  for (int s = 0; s < 60; ++s) env.step(uniformActions(env, 0.0f, 0.0f));
  EXPECT_NEAR(env.view(0).rootState().position.z(), 0.0, 1e-3);
  EXPECT_LT(env.view(0).rootState().comLinearVelocityBody().norm(), 1e-3);
  EXPECT_NEAR(forwardSpeed(model, 5.0f), 5.0 * 0.033, 0.05 * 5.0 * 0.033);
}

TEST(UrdfCases, PackageUriWithoutResolverNamesTheLinkAndUri) {
  expectModelError(
      [] { RobotModel::fromUrdfFile(TRIBOT_URDF); },
      {"link 'base_link'", "package://jetbot_rl/urdf/examples/meshes/chassis.stl", "resolver"});
}

TEST(UrdfCases, AResolverThatFailsIsNamed) {
  expectModelError(
      [] { RobotModel::fromUrdfFile(TRIBOT_URDF, [](const std::string&) { return ""; }); },
      {"link 'base_link'", "package://jetbot_rl/urdf/examples/meshes/chassis.stl",
       "could not be resolved"});
  expectModelError(
      [] {
        RobotModel::fromUrdfFile(TRIBOT_URDF, [](const std::string&) -> std::string {
          throw std::runtime_error("no package 'jetbot_rl'");
        });
      },
      {"link 'base_link'", "package://", "no package 'jetbot_rl'"});
}

TEST(UrdfCases, UnreadableMeshNamesTheLinkAndPath) {
  expectModelError(
      [] { RobotModel::fromUrdfString(tribotWithChassis("file:///nonexistent/chassis.stl")); },
      {"link 'base_link'", "'/nonexistent/chassis.stl'", "cannot be read"});
  expectModelError(
      [] { RobotModel::fromUrdfString(tribotWithChassis("/nonexistent/chassis.stl")); },
      {"link 'base_link'", "'/nonexistent/chassis.stl'"});
  // A file that is no mesh, and one reached through the resolver.
  const std::string junk = writeTempFile("junk.stl", "this is not a mesh\n");
  expectModelError([&] { RobotModel::fromUrdfString(tribotWithChassis(junk)); },
                   {"link 'base_link'", junk});
  expectModelError(
      [] {
        RobotModel::fromUrdfString(tribotWithChassis("package://jetbot_rl/nonexistent.stl"),
                                   testResolver);
      },
      {"link 'base_link'", "nonexistent.stl", "package://jetbot_rl/nonexistent.stl"});
}

TEST(UrdfCases, ZeroMeshScaleIsAnError) {
  const std::string urdf =
      replaceOnce(tribotUrdfText(), "scale=\"0.001 0.001 0.001\"/></geometry>\n    </collision>",
                  "scale=\"0.001 0 0.001\"/></geometry>\n    </collision>");
  expectModelError([&] { RobotModel::fromUrdfString(urdf, testResolver); },
                   {"link 'base_link'", "scale"});
}

TEST(UrdfCases, ObjCasterLoadsFromAPlainPath) {
  // The caster box as an OBJ cube in millimetres (with the chassis' scale of 0.001).
  const std::string obj = writeTempFile("caster.obj",
                                        "v -15 -15 -10\nv 15 -15 -10\nv 15 15 -10\nv -15 15 -10\n"
                                        "v -15 -15 10\nv 15 -15 10\nv 15 15 10\nv -15 15 10\n"
                                        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
                                        "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
  const std::string urdf = replaceOnce(
      tribotUrdfText(), "<geometry><box size=\"0.03 0.03 0.02\"/></geometry>",
      "<geometry><mesh filename=\"" + obj + "\" scale=\"0.001 0.001 0.001\"/></geometry>");
  const auto model = RobotModel::fromUrdfString(urdf, testResolver);
  const CollisionGeometry& caster = model->bodies()[0].collisions[1];
  ASSERT_EQ(caster.type, CollisionGeometry::Type::kMesh);
  EXPECT_EQ(caster.vertices.size(), 8u);
  EXPECT_NEAR(model->restHeight(), tribot()->restHeight(), 1e-9);
  // It stands and drives like the box caster.
  EXPECT_NEAR(forwardSpeed(model, 5.0f), 5.0 * 0.033, 0.05 * 5.0 * 0.033);
}

TEST(UrdfCases, ColladaUnitIsAppliedAndItsUpAxisIgnored) {
  const std::string dae = writeTempFile("tetra.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tetra" name="tetra"><mesh>
      <source id="points">
        <float_array id="coords" count="12">0 0 0 10 0 0 0 20 0 0 0 30</float_array>
        <technique_common><accessor source="#coords" count="4" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="vertices"><input semantic="POSITION" source="#points"/></vertices>
      <triangles count="4"><input semantic="VERTEX" source="#vertices" offset="0"/>
        <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="node">
    <instance_geometry url="#tetra"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)");
  std::vector<Eigen::Vector3d> v = loadMeshHull(dae);
  ASSERT_EQ(v.size(), 4u);
  Eigen::Vector3d high = Eigen::Vector3d::Zero();
  for (const auto& p : v) high = high.cwiseMax(p);
  // Millimetres become metres; y stays y and z stays z (assimp would turn Z_UP into Y_UP).
  EXPECT_TRUE(high.isApprox(Eigen::Vector3d(0.010, 0.020, 0.030), 1e-6)) << high.transpose();
}

TEST(UrdfCases, VisualMeshesAreIgnored) {
  // A visual mesh nobody can read, and no resolver: the Jetbot still loads.
  const std::string urdf =
      replaceOnce(jetbotUrdfText(),
                  "<visual>\n      <origin xyz=\"-0.03 0 0.02\" rpy=\"0 0 0\"/>\n      "
                  "<geometry><box size=\"0.12 0.08 0.05\"/></geometry>",
                  "<visual>\n      <origin xyz=\"-0.03 0 0.02\" rpy=\"0 0 0\"/>\n      "
                  "<geometry><mesh filename=\"package://nowhere/chassis.dae\"/></geometry>");
  EXPECT_NO_THROW(RobotModel::fromUrdfString(urdf));
}

// ---- Caster friction ----

/// Distance the tribot coasts in 1 s from 0.5 m/s with free-wheeling drives.
double coastDistance(double caster_friction) {
  EnvConfig config = tribotConfig(1);
  config.effort_limit = 1e-6;  // [N m]: the wheels turn freely
  config.caster_friction = caster_friction;
  BatchedEnv env(tribot(), config);
  RootState pushed = env.view(0).rootState();
  pushed.com_linear_velocity.x() = 0.5;
  env.setRootState(0, pushed);
  for (int s = 0; s < 60; ++s) env.step(uniformActions(env, 0.0f, 0.0f));
  return env.view(0).rootState().position.x() - pushed.position.x();
}

TEST(UrdfCases, CasterFrictionBrakesASlidingCaster) {
  const double frictionless = coastDistance(0.0);
  const double rough = coastDistance(0.5);
  EXPECT_GT(frictionless, 0.4);  // coasts on (the wheels spin up, the box slides)
  EXPECT_LT(rough, 0.5 * frictionless);
}

// ---- Joint states and the root twist (odometry) ----

TEST(JointStates, EveryMovingJointWithItsDriveEffort) {
  EnvConfig config = smallConfig(1);
  config.decimation = 1;  // efforts are the last physics step's
  BatchedEnv env(jetbot(), config);
  ASSERT_EQ(env.jointNames(), (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
  JointStates js;
  env.view(0).jointStates(js);
  EXPECT_EQ(js.position, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(js.effort, (std::vector<double>{0.0, 0.0}));
  // Starting from rest, the drives push at their 0.08 N m limit, forwards and backwards.
  env.step(uniformActions(env, 20.0f, -20.0f));
  env.view(0).jointStates(js);
  EXPECT_NEAR(js.effort[0], 0.08, 1e-6);
  EXPECT_NEAR(js.effort[1], -0.08, 1e-6);
  for (int s = 0; s < 240; ++s) env.step(uniformActions(env, 10.0f, 10.0f));
  env.view(0).jointStates(js);
  EXPECT_NEAR(js.velocity[0], 10.0, 0.1);
  EXPECT_NEAR(js.velocity[1], env.view(0).dofVelocity(1), 1e-12);
  EXPECT_GT(js.position[0], 10.0);          // [rad]: a second at up to 10 rad/s
  EXPECT_LT(std::abs(js.effort[0]), 0.08);  // cruising needs less than the limit
  const double* data = js.position.data();
  env.view(0).jointStates(js);
  EXPECT_EQ(js.position.data(), data);  // a reused JointStates is not reallocated
  EXPECT_THROW(env.view(1).jointStates(js), InputError);
}

TEST(JointStates, UndrivenJointsHaveNoEffort) {
  EnvConfig config = tribotConfig(1);
  config.dof_names = {"wheel_left_joint"};
  BatchedEnv env(tribot(), config);
  ASSERT_EQ(env.jointNames(), (std::vector<std::string>{"wheel_left_joint", "wheel_right_joint"}));
  for (int s = 0; s < 30; ++s) env.step(std::vector<float>{5.0f});
  JointStates js;
  env.view(0).jointStates(js);
  EXPECT_NE(js.effort[0], 0.0);  // its velocity loop holds it against the scrubbing free wheel
  EXPECT_LE(std::abs(js.effort[0]), 0.3 + 1e-9);
  EXPECT_GT(js.velocity[0], 3.0);  // pivoting about the free wheel, which scrubs
  EXPECT_EQ(js.effort[1], 0.0);
}

TEST(RootTwist, IsTheRootLinkOriginsVelocityInItsFrame) {
  BatchedEnv env(tribot(), tribotConfig(1));
  // Turning in place about base_footprint, the axle's middle: the origin stands, the COM
  // (3 cm behind) circles.
  for (int s = 0; s < 90; ++s) env.step(uniformActions(env, -5.0f, 5.0f));
  const BodyTwist twist = env.view(0).rootTwist();
  const RootState root = env.view(0).rootState();
  EXPECT_GT(twist.angular.z(), 1.5);
  EXPECT_NEAR(twist.angular.z(), (root.orientation.conjugate() * root.angular_velocity).z(), 1e-6);
  EXPECT_LT(twist.linear.norm(), 0.01);
  EXPECT_GT(root.comLinearVelocityBody().norm(), 0.04);
  // Driving straight: forward along the root frame's x, whichever way it faces.
  for (int s = 0; s < 90; ++s) env.step(uniformActions(env, 5.0f, 5.0f));
  const BodyTwist straight = env.view(0).rootTwist();
  EXPECT_NEAR(straight.linear.x(), 5.0 * 0.033, 0.05 * 5.0 * 0.033);
  EXPECT_NEAR(straight.linear.y(), 0.0, 0.005);
  EXPECT_NEAR(straight.angular.z(), 0.0, 0.05);
}

}  // namespace
}  // namespace jetbot_rl
