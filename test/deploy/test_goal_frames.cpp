// The deploy room's goal handling against a real master: goals checked against the map in the
// map's own frame through tf while map -> odom moves (a localisation correcting its drift), a path
// followed through a moving map -> odom, a goal whose client disconnects ended, the goal marker
// cleared when its goal ends and the footprint following the robot.
#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/Marker.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "jetbot_rl/ros/common/geometry_conversion.h"
#include "jetbot_rl/ros/deploy/goal_pursuit.h"
#include "jetbot_rl/ros/deploy/map_input.h"
#include "jetbot_rl/ros/deploy/move_base_server.h"
#include "jetbot_rl/ros/deploy/path_follower.h"

namespace jetbot_rl {
namespace {

using Client = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;
using State = actionlib::SimpleClientGoalState;

/// Spins this node's callbacks until `done` holds or 20 s pass; returns `done()`.
bool spinUntil(const std::function<bool()>& done) {
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!done() && ros::WallTime::now() < give_up && ros::ok()) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  return done();
}

/// A 10 x 10 m map in frame "map" (origin (-5, -5)), free but for a block x in [1, 2], y in
/// [-1, 1].
nav_msgs::OccupancyGrid roomWithABlock() {
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = "map";
  grid.info.resolution = 0.05f;
  grid.info.width = grid.info.height = 200;
  grid.info.origin.position.x = grid.info.origin.position.y = -5.0;
  grid.info.origin.orientation.w = 1.0;
  grid.data.assign(200 * 200, 0);
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const double cx = -5.0 + 0.05 * (x + 0.5), cy = -5.0 + 0.05 * (y + 0.5);
      if (cx > 1.0 && cx < 2.0 && cy > -1.0 && cy < 1.0) grid.data[y * 200 + x] = 100;
    }
  }
  return grid;
}

class GoalFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("/map", 1, true);
    map_pub_.publish(roomWithABlock());
    map_ = std::make_unique<MapInput>(nh_, "/map");
    MoveBaseServerParams p;
    p.goal_topic = "~goal";
    goals_ = std::make_unique<MoveBaseServer>(
        nh_, pnh_, p, *map_, [] { return std::string("odom"); }, [] {}, [] {});
    ASSERT_TRUE(spinUntil([this] { return map_->mapsReceived() > 0; })) << "no map";
    goals_->start();
    client_ = std::make_unique<Client>(nh_, "move_base", false);
    ASSERT_TRUE(spinUntil([this] { return client_->isServerConnected(); })) << "no server";
  }

  /// Broadcasts map -> odom (the odometry frame's pose in the map) and waits until tf has it.
  void setMapOdom(double x, double y, double yaw) {
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time::now();
    t.header.frame_id = "map";
    t.child_frame_id = "odom";
    t.transform.translation.x = x;
    t.transform.translation.y = y;
    tf2::Quaternion q;
    q.setRPY(0.0, 0.0, yaw);
    t.transform.rotation.x = q.x();
    t.transform.rotation.y = q.y();
    t.transform.rotation.z = q.z();
    t.transform.rotation.w = q.w();
    ros::WallTime sent;
    ASSERT_TRUE(spinUntil([&] {
      try {
        const auto held = map_->tf().lookupTransform("map", "odom", ros::Time(0));
        if (held.transform.translation.x == x && held.transform.translation.y == y &&
            held.transform.rotation.z == q.z()) {
          return true;
        }
      } catch (const tf2::TransformException&) {
      }
      // Sent again until tf's latest is it (the listener may not be connected yet).
      if (ros::WallTime::now() - sent > ros::WallDuration(0.1)) {
        t.header.stamp = ros::Time::now();
        broadcaster_.sendTransform(t);
        sent = ros::WallTime::now();
      }
      return false;
    })) << "tf never had map -> odom ("
        << x << ", " << y << ", " << yaw << ")";
  }

  /// Sends a goal at (x, y) in `frame`; returns once it is pursued or has ended.
  State send(double x, double y, const std::string& frame) {
    move_base_msgs::MoveBaseGoal goal;
    goal.target_pose.header.frame_id = frame;
    goal.target_pose.pose.position.x = x;
    goal.target_pose.pose.position.y = y;
    goal.target_pose.pose.orientation.w = 1.0;
    client_->sendGoal(goal);
    EXPECT_TRUE(spinUntil([this] { return client_->getState() != State::PENDING; }));
    EXPECT_TRUE(spinUntil(
        [this] { return client_->getState() != State::ACTIVE || goals_->goal().has_value(); }));
    return client_->getState();
  }

  ros::NodeHandle nh_, pnh_{"~"};
  ros::Publisher map_pub_;
  tf2_ros::TransformBroadcaster broadcaster_;
  std::unique_ptr<MapInput> map_;
  std::unique_ptr<MoveBaseServer> goals_;
  std::unique_ptr<Client> client_;
};

TEST_F(GoalFrames, GoalsAreCheckedInTheMapsFrameThroughTf) {
  setMapOdom(1.5, 0.0, 0.0);
  // (0, 0) in odom is (1.5, 0) in the map: in the block.
  EXPECT_EQ(send(0.0, 0.0, "odom"), State::ABORTED);
  EXPECT_NE(client_->getState().getText().find("in an obstacle of the map"), std::string::npos)
      << client_->getState().getText();
  // (1.5, 0) in odom is (3, 0) in the map: free (the map's cell (1.5, 0) is not).
  ASSERT_EQ(send(1.5, 0.0, "odom"), State::ACTIVE) << client_->getState().getText();
  EXPECT_NEAR(goals_->goalInMap()->x(), 3.0, 1e-9);
  EXPECT_NEAR(goals_->goalInMap()->y(), 0.0, 1e-9);
  EXPECT_NEAR(goals_->goal()->x(), 1.5, 1e-9);
}

TEST_F(GoalFrames, AMovingMapToOdomIsFollowed) {
  setMapOdom(1.5, 0.0, 0.0);
  ASSERT_EQ(send(1.5, 0.0, "odom"), State::ACTIVE) << client_->getState().getText();
  // The localisation corrects by 1.5 m: the same odometry point is now in the block.
  setMapOdom(0.0, 0.0, 0.0);
  EXPECT_EQ(send(1.5, 0.0, "odom"), State::ABORTED);
  // A goal in the map's frame lands in odom where map -> odom puts it, rotation included.
  setMapOdom(0.5, 0.5, 0.5 * M_PI);
  ASSERT_EQ(send(3.0, 0.0, "map"), State::ACTIVE) << client_->getState().getText();
  EXPECT_NEAR(goals_->goal()->x(), -0.5, 1e-6);  // R(-90 deg) (2.5, -0.5)
  EXPECT_NEAR(goals_->goal()->y(), -2.5, 1e-6);
  EXPECT_NEAR(goals_->goalInMap()->x(), 3.0, 1e-9);
}

TEST_F(GoalFrames, APathIsFollowedThroughAMovingMapToOdom) {
  PathFollowing config;
  config.planner.robot_radius = 0.1;
  config.lookahead = 0.5;
  config.blocked_distance = 0.0;
  config.replan_period = 1000.0;  // no re-plan: the plan must follow tf as it is
  PathFollower follower(pnh_, config, map_->tf());
  std::string why;
  ASSERT_TRUE(follower.setMap(occupancyMapOf(roomWithABlock()), "map", why)) << why;
  nav_msgs::Path::ConstPtr published;
  ros::Subscriber plans = pnh_.subscribe<nav_msgs::Path>(
      "plan", 1, [&](const nav_msgs::Path::ConstPtr& m) { published = m; });
  setMapOdom(-3.0, 0.0, 0.0);
  nav_msgs::Odometry odom;  // the robot at odom's origin: (-3, 0) in the map
  odom.header.frame_id = "odom";
  odom.pose.pose.orientation.w = 1.0;
  ASSERT_EQ(follower.plan(Eigen::Vector2d(3.0, 0.0), odom, nullptr), "");
  const auto& points = follower.points();
  ASSERT_GE(points.size(), 3u);  // round the block
  EXPECT_LT((points.front() - Eigen::Vector2d(-3.0, 0.0)).norm(), 0.1);
  for (const Eigen::Vector2d& q : points) {
    EXPECT_FALSE(q.x() > 0.9 && q.x() < 2.1 && q.y() > -1.1 && q.y() < 1.1)
        << "through the block at (" << q.x() << ", " << q.y() << ")";
  }
  ASSERT_TRUE(spinUntil([&] { return published && !published->poses.empty(); }));
  EXPECT_EQ(published->header.frame_id, "map");

  MeasuredState state;
  ASSERT_EQ(follower.follow(odom, nullptr, state), "");
  EXPECT_NEAR(state.goal.x(), 6.0, 1e-6);
  EXPECT_NEAR(state.goal.y(), 0.0, 1e-6);
  const Eigen::Vector2d ahead_in_map = state.lookahead + Eigen::Vector2d(-3.0, 0.0);
  // The localisation moves the robot 0.5 m on in the map: goal and look-ahead follow.
  setMapOdom(-2.5, 0.5, 0.0);
  ASSERT_EQ(follower.follow(odom, nullptr, state), "");
  EXPECT_NEAR(state.goal.x(), 5.5, 1e-6);
  EXPECT_NEAR(state.goal.y(), -0.5, 1e-6);
  EXPECT_GT(state.path_remaining, 0.0);
  // The look-ahead is further along the same plan (in the map), now seen from the new odom.
  const Eigen::Vector2d ahead_now = state.lookahead + Eigen::Vector2d(-2.5, 0.5);
  EXPECT_LT((ahead_now - ahead_in_map).norm(), 0.5 + 0.75);
  EXPECT_NE(ahead_now, ahead_in_map);
}

TEST_F(GoalFrames, APursuedGoalStaysOnTheMapAsMapToOdomMoves) {
  MoveBaseServerParams server;  // a second navigator, without a plan: its goal is the goal
  server.action_name = "pursuit";
  server.goal_topic = "~pursuit_goal";
  server.outcome_topic = "~pursuit_outcome";
  GoalPursuitParams p;
  p.map_topic = "/map";
  p.carrot_distance = 0.0;
  GoalPursuit pursuit(
      nh_, pnh_, p, server, 0.0, 0.1, [] { return std::string("odom"); }, [] {}, [] {});
  setMapOdom(0.0, 0.0, 0.0);
  nav_msgs::Odometry odom;  // the robot at odom's origin, facing +x
  odom.header.frame_id = "odom";
  odom.child_frame_id = "base_link";
  odom.pose.pose.orientation.w = 1.0;
  MeasuredState state;
  PlanarTwist twist;
  GoalPursuit::Mode mode = GoalPursuit::Mode::kStand;
  const auto step = [&] { mode = pursuit.step(odom, nullptr, state, twist); };
  Client client(nh_, "pursuit", false);
  ASSERT_TRUE(spinUntil([&] {
    step();  // its server starts at a step once the map is there
    return client.isServerConnected();
  }));
  move_base_msgs::MoveBaseGoal goal;
  goal.target_pose.header.frame_id = "map";
  goal.target_pose.pose.position.x = 3.0;
  goal.target_pose.pose.orientation.w = 1.0;
  client.sendGoal(goal);
  ASSERT_TRUE(spinUntil([&] {
    step();
    return mode == GoalPursuit::Mode::kPolicy;
  })) << client.getState().getText();
  EXPECT_NEAR(state.goal.x(), 3.0, 1e-6);
  // The localisation moves odom's origin to (0.5, 0.5) in the map: the goal, still at (3, 0) on
  // the map, is at (2.5, -0.5) in odom.
  setMapOdom(0.5, 0.5, 0.0);
  EXPECT_TRUE(spinUntil([&] {
    step();
    return (state.goal - Eigen::Vector2d(2.5, -0.5)).norm() < 1e-6;
  })) << "the goal in odom stayed at ("
      << state.goal.x() << ", " << state.goal.y() << ")";
  EXPECT_EQ(mode, GoalPursuit::Mode::kPolicy);
}

TEST_F(GoalFrames, TheGoalMarkerIsClearedWhenItsGoalEnds) {
  geometry_msgs::PoseStamped::ConstPtr shown;
  visualization_msgs::Marker::ConstPtr arrow;
  int received = 0, arrows = 0;
  ros::Subscriber poses = pnh_.subscribe<geometry_msgs::PoseStamped>(
      "current_goal", 10, [&](const geometry_msgs::PoseStamped::ConstPtr& m) {
        shown = m;
        ++received;
      });
  ros::Subscriber markers = pnh_.subscribe<visualization_msgs::Marker>(
      "current_goal_marker", 10, [&](const visualization_msgs::Marker::ConstPtr& m) {
        arrow = m;
        ++arrows;
      });
  setMapOdom(0.0, 0.0, 0.0);
  ASSERT_EQ(send(3.0, 0.0, "map"), State::ACTIVE) << client_->getState().getText();
  ASSERT_TRUE(spinUntil([&] { return shown && shown->header.frame_id == "map"; }));
  EXPECT_EQ(shown->pose.position.x, 3.0);
  ASSERT_TRUE(spinUntil([&] { return arrow && arrow->action == visualization_msgs::Marker::ADD; }));
  EXPECT_EQ(arrow->header.frame_id, "map");
  EXPECT_EQ(arrow->pose.position.x, 3.0);
  // Reached: the pose is replaced by one without a frame, and RViz's arrow is deleted (a Pose
  // display would keep the last pose it could place).
  int before = received, arrows_before = arrows;
  goals_->succeed();
  ASSERT_TRUE(spinUntil([&] { return received > before && arrows > arrows_before; }));
  EXPECT_EQ(shown->header.frame_id, "");
  EXPECT_EQ(arrow->action, visualization_msgs::Marker::DELETE);
  EXPECT_EQ(arrow->header.frame_id, "map");  // a frame RViz's tf filter knows
  EXPECT_EQ(arrow->ns + std::to_string(arrow->id), "goal0");
  EXPECT_TRUE(spinUntil([&] { return client_->getState() == State::SUCCEEDED; }));
  // Aborted: the same.
  ASSERT_EQ(send(2.5, 0.5, "map"), State::ACTIVE) << client_->getState().getText();
  ASSERT_TRUE(spinUntil([&] {
    return shown->header.frame_id == "map" && arrow->action == visualization_msgs::Marker::ADD;
  }));
  before = received;
  arrows_before = arrows;
  goals_->abort("aborted: by the test");
  ASSERT_TRUE(spinUntil([&] { return received > before && arrows > arrows_before; }));
  EXPECT_EQ(shown->header.frame_id, "");
  EXPECT_EQ(arrow->action, visualization_msgs::Marker::DELETE);
  // A refused goal was never shown: nothing is cleared for it.
  before = received;
  arrows_before = arrows;
  EXPECT_EQ(send(1.5, 0.0, "map"), State::ABORTED);  // in the block
  ros::WallDuration(0.3).sleep();
  ros::spinOnce();
  EXPECT_EQ(received, before);
  EXPECT_EQ(arrows, arrows_before);
}

TEST_F(GoalFrames, TheFootprintFollowsTheRobot) {
  MoveBaseServerParams server;  // a navigator with plans (a carrot): it shows its footprint
  server.action_name = "footprint_pursuit";
  server.goal_topic = "~footprint_goal";
  server.outcome_topic = "~footprint_outcome";
  GoalPursuitParams p;
  p.map_topic = "/map";
  GoalPursuit pursuit(
      nh_, pnh_, p, server, 0.0, 0.1, [] { return std::string("odom"); }, [] {}, [] {});
  std::vector<geometry_msgs::PolygonStamped::ConstPtr> footprints;
  ros::Subscriber sub = pnh_.subscribe<geometry_msgs::PolygonStamped>(
      "footprint", 10,
      [&](const geometry_msgs::PolygonStamped::ConstPtr& m) { footprints.push_back(m); });
  nav_msgs::Odometry odom;
  odom.header.frame_id = "odom";
  odom.child_frame_id = "robot/base_link";
  odom.pose.pose.orientation.w = 1.0;
  MeasuredState state;
  PlanarTwist twist;
  // A moving robot's control steps (repeated until the subscription is connected): each
  // footprint has the odometry's stamp.
  for (int k = 0; k < 3; ++k) {
    odom.header.stamp = ros::Time(100.0 + k);
    odom.pose.pose.position.x = 0.5 * k;
    state.root = rootStateOf(odom);
    ASSERT_TRUE(spinUntil([&] {
      EXPECT_EQ(pursuit.step(odom, nullptr, state, twist), GoalPursuit::Mode::kStand);
      return !footprints.empty() && footprints.back()->header.stamp == odom.header.stamp;
    })) << "no footprint stamped "
        << odom.header.stamp;
    const geometry_msgs::PolygonStamped& f = *footprints.back();
    EXPECT_EQ(f.header.frame_id, "robot/base_link");  // tf places it where the robot is then
    ASSERT_EQ(f.polygon.points.size(), 24u);
    for (const geometry_msgs::Point32& q : f.polygon.points) {
      EXPECT_NEAR(std::hypot(q.x, q.y), 0.1, 1e-6);  // round the robot's origin
    }
  }
}

TEST_F(GoalFrames, AGoalWhoseClientDisconnectsEnds) {
  setMapOdom(0.0, 0.0, 0.0);
  ASSERT_EQ(send(3.0, 0.0, "map"), State::ACTIVE) << client_->getState().getText();
  std::string why;
  EXPECT_FALSE(goals_->clientGone(why)) << why;
  client_.reset();  // the mission script exits: its connections to the action close
  ASSERT_TRUE(spinUntil([&] { return goals_->clientGone(why); }));
  EXPECT_NE(why.find(ros::this_node::getName()), std::string::npos) << why;
}

TEST_F(GoalFrames, AGoalSentOnTheTopicByHandIsNotWatched) {
  setMapOdom(0.0, 0.0, 0.0);
  client_.reset();  // no client at all: as `rostopic pub move_base/goal ...`
  ros::Publisher raw = nh_.advertise<move_base_msgs::MoveBaseActionGoal>("move_base/goal", 1);
  move_base_msgs::MoveBaseActionGoal goal;
  goal.goal.target_pose.header.frame_id = "map";
  goal.goal.target_pose.pose.position.x = 3.0;
  goal.goal.target_pose.pose.orientation.w = 1.0;
  ASSERT_TRUE(spinUntil([&] { return raw.getNumSubscribers() > 0; }));
  raw.publish(goal);
  ASSERT_TRUE(spinUntil([&] { return goals_->goal().has_value(); }));
  std::string why;
  EXPECT_FALSE(goals_->clientGone(why)) << why;
}

}  // namespace
}  // namespace jetbot_rl

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_goal_frames");
  ros::NodeHandle nh;  // keeps the node up between tests
  return RUN_ALL_TESTS();
}
