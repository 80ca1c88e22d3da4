#!/usr/bin/python3
"""Closed loop with a navigation policy, as on a robot: a policy trained in the arena with random
obstacles (train.launch task:=navigation) drives the env node's lidar Jetbot in the office map
through jetbot_deploy_node (scan and odometry in, cmd_vel out). A goal sent as RViz's
"2D Nav Goal" sends it (PoseStamped on /move_base_simple/goal, in the map frame) is reached within
a time bound without touching anything (no scan reading below range_min), past a person pacing
across its way (person_crossing.yaml, seen on the env node's markers); goals in an obstacle or
with a non-finite pose are refused, and the robot stays stopped."""
import math
import time

import rospy
import rostest
from visualization_msgs.msg import MarkerArray

from jetbot_rl_test.deployed_navigation import DeployedNavigation, goal_msg
from jetbot_rl_test.env_client import wait_for

GOAL = (1.5, -0.5)        # env frame (= env_0/map frame): free, 1.6 m from the start
REACH_WITHIN = 40.0       # [s]


class TestClosedLoopNavigation(DeployedNavigation):
    node_name = 'test_closed_loop_navigation'

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.sightings = []  # (time, robot x, y, person x, y) from the env node's markers
        rospy.Subscriber('/jetbot_env/markers', MarkerArray, cls.on_markers)

    @classmethod
    def on_markers(cls, msg):
        robot = [m.pose.position for m in msg.markers if m.ns == 'body' and m.id == 0]
        person = [m.pose.position for m in msg.markers if m.ns == 'movers' and m.id == 0]
        if robot and person:
            cls.sightings.append((time.monotonic(), robot[0].x, robot[0].y, person[0].x,
                                  person[0].y))

    def test_1_goals_in_an_obstacle_or_not_finite_are_refused(self):
        start = self.position()
        self.send(goal_msg(2.25, -2.0), 'refused')       # the table
        self.send(goal_msg(float('nan'), 0.0), 'refused')
        self.assert_still(start)

    def test_2_a_goal_from_rviz_is_reached_past_a_person_without_touching_anything(self):
        wait_for(lambda: self.sightings, what='the person on the markers')
        first_scan = len(self.scans)
        count = self.send(goal_msg(*GOAL), 'accepted')
        sent = time.monotonic()
        wait_for(lambda: len(self.outcomes) > count + 1, timeout=REACH_WITHIN,
                 what='the goal to be reached')
        took = time.monotonic() - sent
        self.assertEqual(self.outcomes[count + 1], 'reached')
        x, y = self.position()
        print('FIGURE: navigation closed loop: goal (%.1f, %.1f) reached in %.1f s, at (%.2f, %.2f)'
              % (GOAL[0], GOAL[1], took, x, y))
        self.assertLess(math.hypot(x - GOAL[0], y - GOAL[1]), 0.3)
        closest = min(min(r for r in s.ranges) for s in self.scans[first_scan:])
        print('FIGURE: navigation closed loop: closest scan reading %.3f m' % closest)
        self.assertGreater(closest, float('-inf'), 'a scan read below range_min: a touch')
        # The person walked (its path, which the robot's approach may slow: people avoid it) and
        # the robot passed near it.
        during = [s for s in self.sightings if sent <= s[0] <= sent + took]
        self.assertTrue(during, 'no markers while the robot drove')
        walked = [s for s in self.sightings if s[0] <= sent + took]
        path = sum(math.hypot(b[3] - a[3], b[4] - a[4]) for a, b in zip(walked, walked[1:]))
        nearest = min(math.hypot(s[1] - s[3], s[2] - s[4]) for s in during)
        print('FIGURE: navigation closed loop: the person walked %.2f m in %.1f s; nearest centre '
              'distance to the robot %.2f m' % (path, walked[-1][0] - walked[0][0], nearest))
        self.assertGreater(path, 0.5, 'the person did not walk')
        self.assertLess(nearest, 1.2, 'the robot never came near the person')


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_closed_loop_navigation', TestClosedLoopNavigation)
