"""Test helpers for a navigation policy deployed on the env node's robot: a shipped policy
(policies/README.md), run by jetbot_deploy_node on env 0's scan, odometry and cmd_vel with the map, send goals as RViz's
"2D Nav Goal" sends them and record odometry, scans, outcomes and plans."""
import math
import os
import signal
import subprocess
import time
import unittest

import actionlib
import rospkg
import rospy
from geometry_msgs.msg import PoseStamped
from move_base_msgs.msg import MoveBaseAction
from nav_msgs.msg import Odometry, Path
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for


REACH_WITHIN = 90.0  # [s]: a goal in another room of maps/office.yaml


def length(points):
    return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))


def goal_msg(x, y, frame='env_0/map'):
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.header.stamp = rospy.Time(0)
    msg.pose.position.x = x
    msg.pose.position.y = y
    msg.pose.orientation.w = 1.0
    return msg


class DeployedNavigation(unittest.TestCase):
    """Deploys the shipped policy `shipped_policy` (by default policies/navigation_arena: 200 iterations in
    the small arena of config/navigation_arena.yaml, no path observed) once per class as /deploy
    (`deploy_args` added)."""
    node_name = 'test_deployed_navigation'
    shipped_policy = 'navigation_arena'
    deploy_args = []

    @classmethod
    def setUpClass(cls):
        rospy.init_node(cls.node_name)
        cls.run_dir = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies',
                                   cls.shipped_policy)
        cls.odoms, cls.scans, cls.outcomes, cls.plans = (EventList(), EventList(), EventList(),
                                                         EventList())
        rospy.Subscriber('/env_0/odom', Odometry, cls.odoms.append)
        rospy.Subscriber('/env_0/scan', LaserScan, cls.scans.append)
        rospy.Subscriber('/deploy/outcome', String, lambda m: cls.outcomes.append(m.data))
        rospy.Subscriber('/deploy/plan', Path, cls.plans.append)
        cls.goal_pub = rospy.Publisher('/move_base_simple/goal', PoseStamped, queue_size=1,
                                       latch=True)
        cls.policy = cls.deploy('deploy', cls.deploy_args)
        wait_for(lambda: cls.odoms and cls.scans, what='odometry and scans')
        wait_for(lambda: cls.goal_pub.get_num_connections() > 0, what='the policy node',
                 recheck=0.2)
        # Its move_base action starts once its odometry, scan and map are there: it takes goals.
        cls.client = actionlib.SimpleActionClient('move_base', MoveBaseAction)
        assert cls.client.wait_for_server(rospy.Duration(TIMEOUT)), 'no move_base action server'

    @classmethod
    def deploy(cls, name, args):
        """Starts jetbot_deploy_node `name` on env 0 with the trained policy, `args` added
        ('_param:=value')."""
        return subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=' + name,
            '_checkpoint:=' + cls.run_dir, '_task:=navigation',
            '_odom_topic:=/env_0/odom',
            '_scan_topic:=/env_0/scan', '_cmd_vel_topic:=/env_0/cmd_vel',
            '_map_topic:=/map'] + list(args))

    @classmethod
    def tearDownClass(cls):
        cls.policy.send_signal(signal.SIGINT)
        cls.policy.wait(timeout=TIMEOUT)

    def send(self, msg, outcome):
        """Publishes the goal `msg`; its first outcome must start with `outcome`. Returns the
        outcomes' count before it."""
        count = len(self.outcomes)
        self.goal_pub.publish(msg)
        wait_for(lambda: len(self.outcomes) > count, what='the goal\'s outcome')
        self.assertTrue(self.outcomes[count].startswith(outcome), self.outcomes[count])
        return count

    def position(self):
        p = self.odoms[-1].pose.pose.position
        return p.x, p.y

    def assert_still(self, start):
        """A second of odometry (50 Hz) later the robot is where it was: it would have moved."""
        seen = len(self.odoms)
        wait_for(lambda: len(self.odoms) > seen + 50, what='a second of odometry')
        end = self.position()
        self.assertLess(((end[0] - start[0]) ** 2 + (end[1] - start[1]) ** 2) ** 0.5, 0.02)

    def reach(self, goal, label):
        """Sends `goal` (in another room: the plan turns round a wall), waits for its plan and
        arrival within REACH_WITHIN without a scan reading below range_min (a touch); prints the
        FIGURE lines under `label`; returns the plan's points."""
        start = self.position()
        first_scan, plans = len(self.scans), len(self.plans)
        count = self.send(goal_msg(*goal), 'accepted')
        sent = time.monotonic()
        # The first plan with poses: an empty one ends the previous goal's.
        wait_for(lambda: any(p.poses for p in self.plans[plans:]), what='the plan')
        plan = next(p for p in self.plans[plans:] if p.poses)
        self.assertEqual(plan.header.frame_id, 'env_0/map')
        points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
        self.assertGreaterEqual(len(points), 3, points)  # round a wall: it turns
        self.assertLess(math.hypot(points[0][0] - start[0], points[0][1] - start[1]), 0.3)
        self.assertAlmostEqual(points[-1][0], goal[0], places=3)
        self.assertAlmostEqual(points[-1][1], goal[1], places=3)
        wait_for(lambda: len(self.outcomes) > count + 1, timeout=REACH_WITHIN,
                 what='the goal (%.1f, %.1f) to be reached' % goal)
        took = time.monotonic() - sent
        self.assertEqual(self.outcomes[count + 1], 'reached')
        x, y = self.position()
        print('FIGURE: %s: goal (%.1f, %.1f) behind a wall reached in %.1f s at (%.2f, %.2f); '
              'plan %.2f m (straight line %.2f m), %d points'
              % (label, goal[0], goal[1], took, x, y, length(points),
                 math.hypot(goal[0] - start[0], goal[1] - start[1]), len(points)))
        self.assertLess(math.hypot(x - goal[0], y - goal[1]), 0.3)
        closest = min(min(r for r in s.ranges) for s in self.scans[first_scan:])
        print('FIGURE: %s: closest scan reading %.3f m' % (label, closest))
        self.assertGreater(closest, float('-inf'), 'a scan read below range_min: a touch')
        return points
