#!/usr/bin/python3
"""Closed loop with a policy that follows a global path, as on a robot: the shipped navigator
(policies/navigation: as train.launch task:=navigation trains it: generated worlds, nav/path), it drives the
env node's lidar Jetbot in the office map through jetbot_deploy_node, which plans on /map. A goal behind a wall, in the room above, and
then one in the room on the other side of the floor are reached through the doors within a time
bound without touching anything, each with a plan on ~plan that goes round the walls; a goal
too near a wall for the footprint ends with no path, and the robot stays stopped."""
import rostest

from jetbot_rl_test.deployed_navigation import DeployedNavigation, goal_msg
from jetbot_rl_test.env_client import wait_for

# env frame (= env_0/map): the start (0, 0) is in the lower right room of maps/office.yaml
ABOVE = (0.0, 2.0)       # the room above, behind the wall at y = 0.5; its door is at x in [1, 2]
OTHER_SIDE = (-3.0, 0.0)  # the left half, behind the wall at x = -1; its door at y in [-1.5, -0.5]
NEAR_WALL = (-0.87, 2.0)  # a free cell 3 cm from the wall at x = -0.9: within the footprint


class TestClosedLoopPath(DeployedNavigation):
    node_name = 'test_closed_loop_path'
    shipped_policy = 'navigation'  # the task's defaults

    def test_1_a_goal_too_near_a_wall_has_no_path(self):
        start = self.position()
        count = self.send(goal_msg(*NEAR_WALL), 'accepted')
        wait_for(lambda: len(self.outcomes) > count + 1, what='the goal\'s end')
        self.assertTrue(self.outcomes[count + 1].startswith('no path:'), self.outcomes[count + 1])
        self.assertIn('footprint', self.outcomes[count + 1])
        self.assert_still(start)

    def test_2_a_goal_behind_a_wall_is_reached_through_the_door(self):
        points = self.reach(ABOVE, 'path closed loop')
        # The plan goes through the door (x in [1, 2]) where it crosses the wall at y = 0.5.
        for a, b in zip(points, points[1:]):
            if (a[1] - 0.5) * (b[1] - 0.5) <= 0.0 and a[1] != b[1]:
                x = a[0] + (b[0] - a[0]) * (0.5 - a[1]) / (b[1] - a[1])
                self.assertTrue(1.0 < x < 2.0, points)

    def test_3_a_goal_across_the_floor_is_reached(self):
        self.reach(OTHER_SIDE, 'path closed loop')


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_closed_loop_path', TestClosedLoopPath)
