// The deploy node takes what training knew from the checkpoint's observation contract (the robot's
// wheel geometry and footprint, the goal radius, a path's clearance): parameters left unset take
// it, one given anyway is kept and named, with the checkpoint's value, in a warning.
#include <gtest/gtest.h>

#include "jetbot_rl/ros/deploy/deploy_params.h"
#include "jetbot_rl/tasks/navigation_task.h"

namespace jetbot_rl {
namespace {

ObserverSpec pathPolicy() {
  ObserverSpec o;
  o.scan_beam_angles = {0.0};
  o.scan_range = {0.15, 3.5};
  o.goal_radius = 0.25;
  o.path_lookahead = 0.6;
  o.path_clearance = 0.4;
  o.path_clearance_cost = 3.0;
  o.wheel_radius = 0.03;
  o.wheel_separation = 0.12;
  o.footprint_radius = 0.09;
  return o;
}

TEST(TrainedSettings, UnsetParametersTakeTheCheckpointsWithoutAWarning) {
  DeployParams p;
  EXPECT_TRUE(takeTrainedSettings(p, pathPolicy()).empty());
  EXPECT_EQ(p.driver.wheel_radius, 0.03);
  EXPECT_EQ(p.driver.wheel_separation, 0.12);
  EXPECT_EQ(p.pursuit.xy_goal_tolerance, 0.25);
  EXPECT_EQ(p.pursuit.footprint_radius, 0.09);
  EXPECT_EQ(p.pursuit.path_clearance, 0.4);
  EXPECT_EQ(p.pursuit.path_clearance_cost, 3.0);
}

TEST(TrainedSettings, AGivenParameterOverridesTheCheckpointsNamingBothValues) {
  DeployParams p;
  p.driver.wheel_radius = 0.03015;
  p.pursuit.xy_goal_tolerance = 0.3;
  p.pursuit.path_clearance = 0.0;     // 0 is a clearance, not "unset"
  p.pursuit.footprint_radius = 0.09;  // the checkpoint's: no warning
  const std::vector<std::string> lines = takeTrainedSettings(p, pathPolicy());
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "wheel_radius = 0.03015 overrides the checkpoint's wheel_radius = 0.03",
                       "xy_goal_tolerance = 0.3 overrides the checkpoint's goal_radius = 0.25",
                       "path_clearance = 0 overrides the checkpoint's path_clearance = 0.4"}));
  EXPECT_EQ(p.driver.wheel_radius, 0.03015);
  EXPECT_EQ(p.driver.wheel_separation, 0.12);
  EXPECT_EQ(p.pursuit.xy_goal_tolerance, 0.3);
  EXPECT_EQ(p.pursuit.path_clearance, 0.0);
  EXPECT_EQ(p.pursuit.path_clearance_cost, 3.0);
}

TEST(TrainedSettings, APolicyWithoutAPathPlansACarrotsPathAsTheTaskWould) {
  ObserverSpec o = pathPolicy();
  o.path_lookahead = o.path_clearance = o.path_clearance_cost = 0.0;
  DeployParams p;
  EXPECT_TRUE(takeTrainedSettings(p, o).empty());
  EXPECT_EQ(p.pursuit.path_clearance, NavigationConfig().path_clearance);
  EXPECT_EQ(p.pursuit.path_clearance_cost, NavigationConfig().path_clearance_cost);
}

TEST(TrainedSettings, ARobotWithoutADifferentialDriveLeavesTheWheelsToRobotDescription) {
  ObserverSpec o = pathPolicy();
  o.wheel_radius = o.wheel_separation = 0.0;
  DeployParams p;
  EXPECT_TRUE(takeTrainedSettings(p, o).empty());
  EXPECT_EQ(p.driver.wheel_radius, 0.0);  // makeKinematics() reads robot_description then
  EXPECT_EQ(p.driver.wheel_separation, 0.0);
}

}  // namespace
}  // namespace jetbot_rl
