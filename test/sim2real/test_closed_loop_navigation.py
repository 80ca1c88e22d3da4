#!/usr/bin/python3
"""Closed loop with a navigation policy, as on a robot: a policy trained in the arena with random
obstacles (train.launch task:=navigation) drives the env node's lidar Jetbot in the office map
through jetbot_deploy_node (scan and odometry in, cmd_vel out). A goal sent as RViz's
"2D Nav Goal" sends it (PoseStamped on /move_base_simple/goal, in the map frame) is reached within
a time bound without touching anything (no scan reading below range_min); goals in an obstacle or
with a non-finite pose are refused, and the robot stays stopped."""
import math
import signal
import subprocess
import tempfile
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for

GOAL = (1.5, -0.5)        # env frame (= env_0/map frame): free, 1.6 m from the start
REACH_WITHIN = 40.0       # [s]


def goal_msg(x, y, frame='env_0/map'):
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.header.stamp = rospy.Time(0)
    msg.pose.position.x = x
    msg.pose.position.y = y
    msg.pose.orientation.w = 1.0
    return msg


class TestClosedLoopNavigation(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_closed_loop_navigation')
        cls.run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_nav_')
        subprocess.run(['roslaunch', 'jetbot_rl', 'train.launch', 'in_process:=true',
                        'task:=navigation', 'iterations:=200', 'run_dir:=' + cls.run_dir,
                        'output:=log'], check=True, timeout=10 * TIMEOUT, stdout=subprocess.DEVNULL)
        with open(cls.run_dir + '/summary.yaml') as f:
            print(f.read())
        cls.odoms, cls.scans, cls.outcomes = EventList(), EventList(), EventList()
        rospy.Subscriber('/env_0/odom', Odometry, cls.odoms.append)
        rospy.Subscriber('/env_0/scan', LaserScan, cls.scans.append)
        rospy.Subscriber('/deploy/outcome', String, lambda m: cls.outcomes.append(m.data))
        cls.goal_pub = rospy.Publisher('/move_base_simple/goal', PoseStamped, queue_size=1,
                                       latch=True)
        cls.policy = subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=deploy',
            '_checkpoint:=' + cls.run_dir, '_task:=navigation',
            '_odom_topic:=/env_0/odom',
            '_scan_topic:=/env_0/scan', '_cmd_vel_topic:=/env_0/cmd_vel', '_map_topic:=/map',
            '_wheel_radius:=0', '_wheel_separation:=0'])
        wait_for(lambda: cls.odoms and cls.scans, what='odometry and scans')
        wait_for(lambda: cls.goal_pub.get_num_connections() > 0, what='the policy node',
                 recheck=0.2)

    @classmethod
    def tearDownClass(cls):
        cls.policy.send_signal(signal.SIGINT)
        cls.policy.wait(timeout=TIMEOUT)

    def send(self, msg, outcome):
        count = len(self.outcomes)
        self.goal_pub.publish(msg)
        wait_for(lambda: len(self.outcomes) > count, what='the goal\'s outcome')
        self.assertTrue(self.outcomes[count].startswith(outcome), self.outcomes[count])
        return count

    def position(self):
        p = self.odoms[-1].pose.pose.position
        return p.x, p.y

    def test_1_goals_in_an_obstacle_or_not_finite_are_refused(self):
        start = self.position()
        self.send(goal_msg(2.25, -2.0), 'refused')       # the table
        self.send(goal_msg(float('nan'), 0.0), 'refused')
        # A second of odometry (50 Hz): the robot would have moved by then.
        seen = len(self.odoms)
        wait_for(lambda: len(self.odoms) > seen + 50, what='a second of odometry')
        end = self.position()
        self.assertLess(math.hypot(end[0] - start[0], end[1] - start[1]), 0.02)

    def test_2_a_goal_from_rviz_is_reached_without_touching_anything(self):
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


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_closed_loop_navigation', TestClosedLoopNavigation)
