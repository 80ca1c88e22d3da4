#!/usr/bin/python3
"""jetbot_deploy_node with the shipped mix navigator (policies/navigation_mix, whose checkpoint
names the speed limit it drives behind: docs/navigation.md#the-speed-limit), fed by this test's
own odometry (the robot standing at the origin, facing +x), LaserScan and map (6 x 6 m, all free,
in the odometry frame), with a goal 1.5 m straight ahead: the node says at start-up that it limits the forward speed as the checkpoint
does; with something 0.155 m ahead of the scanner (0.095 m ahead of the Jetbot's front: inside
the 0.1 m stop distance) its status reports that distance and every Twist has v 0; once the scan
is clear the status reports nothing ahead and the policy drives forward."""
import math
import os
import subprocess
import tempfile
import threading
import time
import unittest

import rospkg
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan

from jetbot_rl_test.env_client import EventList, wait_for

NODE = '/deploy'
SAMPLES = 360
NEAR = 0.155           # [m] from the scanner, within 10 degrees of ahead
FRONT = 0.06           # [m]: the Jetbot's front ahead of its scanner (urdf/jetbot_lidar.urdf)
CLEAR_KEY = 'speed limit: clear ahead [m]'


def odometry():
    msg = Odometry()
    msg.header.frame_id = 'odom'
    msg.child_frame_id = 'base_link'
    msg.pose.pose.orientation.w = 1.0
    return msg


def free_map():
    msg = OccupancyGrid()
    msg.header.frame_id = 'odom'
    msg.info.resolution = 0.05
    msg.info.width = msg.info.height = 120
    msg.info.origin.position.x = msg.info.origin.position.y = -3.0
    msg.info.origin.orientation.w = 1.0
    msg.data = [0] * (120 * 120)
    return msg


def scan(near):
    msg = LaserScan()
    msg.header.frame_id = 'lidar_link'
    msg.angle_min = -math.pi
    msg.angle_increment = 2 * math.pi / SAMPLES
    msg.angle_max = msg.angle_min + (SAMPLES - 1) * msg.angle_increment
    msg.range_min = 0.15
    msg.range_max = 3.5
    msg.ranges = [float('inf')] * SAMPLES
    if near:
        for k in range(SAMPLES):
            if abs(msg.angle_min + k * msg.angle_increment) <= math.radians(10):
                msg.ranges[k] = NEAR
    return msg


class Sensors(object):
    """Publishes fresh odometry and scans at 20 Hz (wall), the scan with or without the
    obstacle: a robot's drivers."""

    def __init__(self):
        self.odom_pub = rospy.Publisher('/robot/odom', Odometry, queue_size=10)
        self.scan_pub = rospy.Publisher('/robot/scan', LaserScan, queue_size=10)
        self.near = True
        threading.Thread(target=self.loop, daemon=True).start()

    def loop(self):
        while not rospy.is_shutdown():
            stamp = rospy.Time.now()
            o, s = odometry(), scan(self.near)
            o.header.stamp = s.header.stamp = stamp
            self.odom_pub.publish(o)
            self.scan_pub.publish(s)
            time.sleep(0.05)  # a sensor's rate, not a synchronisation


class TestDeploySpeedLimit(unittest.TestCase):
    def test_the_checkpoints_limit_caps_the_robots_own_scan(self):
        run_dir = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies',
                               'navigation_mix')
        twists, statuses, messages = EventList(), EventList(), EventList()
        rospy.Subscriber('/robot/cmd_vel', Twist, twists.append)

        def on_diagnostics(msg):
            for status in msg.status:
                if status.name == NODE + ': deploy':
                    statuses.append({kv.key: kv.value for kv in status.values})
                    messages.append(status.message)
        rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics)
        sensors = Sensors()
        goal_pub = rospy.Publisher('/move_base_simple/goal', PoseStamped, queue_size=1,
                                   latch=True)
        map_pub = rospy.Publisher('/robot/map', OccupancyGrid, queue_size=1, latch=True)
        map_pub.publish(free_map())
        output = tempfile.NamedTemporaryFile(prefix='jetbot_rl_test_deploy_speed_limit_',
                                             suffix='.log')
        proc = subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=' + NODE[1:],
            '_checkpoint:=' + run_dir, '_odom_topic:=/robot/odom', '_scan_topic:=/robot/scan',
            '_cmd_vel_topic:=/robot/cmd_vel', '_map_topic:=/robot/map'], stdout=output, stderr=subprocess.STDOUT,
            env=dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1'))
        try:
            def lines():
                with open(output.name) as f:
                    return f.read().splitlines()
            wait_for(lambda: any('forward speed limited as in training' in line
                                 for line in lines()),
                     what="the node's start-up line naming the checkpoint's speed limit")
            line = [x for x in lines() if 'forward speed limited' in x][0]
            self.assertIn('0 within 0.1 m ahead of the front, full beyond 0.25 m', line)
            # Fresh inputs and no goal yet: then a goal is taken (not refused for want of odometry).
            wait_for(lambda: messages and messages[-1] == 'standing: no goal',
                     what="the node's status standing for a goal on fresh inputs")
            goal = PoseStamped()
            goal.header.frame_id = 'odom'
            goal.pose.position.x = 1.5
            goal.pose.orientation.w = 1.0
            goal_pub.publish(goal)

            # Something inside the stop distance ahead: the policy acts, v stays 0.
            wait_for(lambda: statuses and CLEAR_KEY in statuses[-1],
                     what='a status with what is clear ahead')
            expected = NEAR * math.cos(math.radians(10)) - FRONT  # the nearest in the path
            self.assertAlmostEqual(float(statuses[-1][CLEAR_KEY]), expected, delta=0.003)
            count = len(twists)
            wait_for(lambda: len(twists) >= count + 20, what='20 Twists of the policy')
            blocked = twists[count:]
            self.assertTrue(all(t.linear.x == 0.0 for t in blocked),
                            'v with something %.3f m ahead: %s'
                            % (expected, [t.linear.x for t in blocked]))

            # The scan clears: nothing ahead, and the policy drives to its goal.
            sensors.near = False
            wait_for(lambda: statuses and math.isinf(float(statuses[-1][CLEAR_KEY])),
                     what='a status with nothing ahead')
            wait_for(lambda: any(t.linear.x > 0.1 for t in twists[-5:]),
                     what='the policy driving forward on a clear scan')
            print('FIGURE: deploy speed limit: v 0 in %d Twists with %.3f m clear ahead; '
                  'v %.2f m/s once clear' % (len(blocked), expected, twists[-1].linear.x))
        finally:
            proc.terminate()
            proc.wait(timeout=10)


if __name__ == '__main__':
    rospy.init_node('test_deploy_speed_limit')
    rostest.rosrun('jetbot_rl', 'deploy_speed_limit', TestDeploySpeedLimit)
