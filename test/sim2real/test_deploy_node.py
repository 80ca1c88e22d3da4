#!/usr/bin/python3
"""jetbot_deploy_node (the shipped velocity policy, a wheel radius given that overrides the
checkpoint's with a warning) fed by this test's own odometry publisher: a moving Twist while odometry is
fresh (its 1 Hz status OK, "driving"); zero Twists once it stops coming (odom_timeout; the status
WARN, "standing: no fresh odometry ..."); non-finite odometry dropped, counted on /diagnostics,
the robot kept stopped; moving again on fresh odometry; after SIGINT a zero Twist last and exit
status 0 within 2 s."""
import math
import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import rospkg
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for

NODE = '/deploy'
ODOM_TIMEOUT = 0.3  # [s]
NAN_ODOMS = 5
DRIVER_WHEEL_RADIUS = 0.03015  # [m]: the stock Jetbot driver's (the simulated Jetbot's is 0.03)


def is_zero(twist):
    return all(v == 0.0 for v in (twist.linear.x, twist.linear.y, twist.linear.z,
                                  twist.angular.x, twist.angular.y, twist.angular.z))


def odometry(vx, x=0.0):
    msg = Odometry()
    msg.header.frame_id = 'odom'
    msg.child_frame_id = 'base_link'
    msg.pose.pose.position.x = x
    msg.pose.pose.orientation.w = 1.0
    msg.twist.twist.linear.x = vx
    return msg


class OdometrySource(object):
    """Publishes fresh odometry at 50 Hz (wall) while `running`: a robot's odometry node."""

    def __init__(self, pub):
        self.pub = pub
        self.running = threading.Event()
        self.thread = threading.Thread(target=self.loop, daemon=True)
        self.thread.start()

    def loop(self):
        while not rospy.is_shutdown():
            self.running.wait()
            self.pub.publish(odometry(0.1))
            time.sleep(0.02)  # a sensor's rate, not a synchronisation


class TestDeployNode(unittest.TestCase):
    def test_deploy_node_faults(self):
        run_dir = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies', 'velocity')
        twists, drops, states = EventList(), EventList(), EventList()
        rospy.Subscriber('/robot/cmd_vel', Twist, twists.append)

        def on_diagnostics(msg):
            for status in msg.status:
                values = {kv.key: kv.value for kv in status.values}
                if status.name == NODE + ': deploy input':
                    drops.append(values)
                elif status.name == NODE + ': deploy':
                    states.append((status.level, status.message, values))
        rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics)
        odom_pub = rospy.Publisher('/robot/odom', Odometry, queue_size=10)
        source = OdometrySource(odom_pub)
        output = tempfile.NamedTemporaryFile(prefix='jetbot_rl_test_deploy_node_', suffix='.log')
        proc = subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=' + NODE[1:],
            '_checkpoint:=' + run_dir, '_odom_topic:=/robot/odom',
            '_cmd_vel_topic:=/robot/cmd_vel', '_odom_timeout:=%g' % ODOM_TIMEOUT,
            '_wheel_radius:=%g' % DRIVER_WHEEL_RADIUS], stdout=output, stderr=subprocess.STDOUT,
            env=dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1'))  # INFO lines as they come
        try:
            # The wheel radius given overrides the trained robot's, which the checkpoint holds:
            # said once, at WARN, naming both; the separation not given is the checkpoint's.
            # (read from its output: /rosout may connect after the start-up's lines)
            def lines():
                with open(output.name) as f:
                    return f.read().splitlines()
            wait_for(lambda: any('overrides' in line for line in lines()),
                     what="the node's warning of the wheel radius given")
            warnings = [line for line in lines() if 'overrides' in line]
            self.assertEqual(len(warnings), 1, warnings)
            self.assertIn('[ WARN]', warnings[0])
            self.assertIn('%s: wheel_radius = %g overrides the checkpoint\'s wheel_radius = 0.03'
                          % (NODE, DRIVER_WHEEL_RADIUS), warnings[0])
            in_use = 'wheel_radius %g m, wheel_separation 0.1125 m' % DRIVER_WHEEL_RADIUS
            wait_for(lambda: any(in_use in line for line in lines()),
                     what="the node's line of the settings in use (%s)" % in_use)
            wait_for(lambda: odom_pub.get_num_connections() > 0, what='the node to subscribe',
                     recheck=0.05)
            wait_for(lambda: twists, what='Twists (no odometry yet)')
            self.assertTrue(is_zero(twists[-1]), 'no odometry yet, yet %s' % twists[-1])

            source.running.set()
            wait_for(lambda: twists and not is_zero(twists[-1]),
                     what='a moving Twist on fresh odometry')
            count = len(states)
            wait_for(lambda: len(states) > count, what="the node's status while it drives")
            self.assertEqual(states[-1][:2], (DiagnosticStatus.OK, 'driving'))

            source.running.clear()
            stopped_at = time.monotonic()
            wait_for(lambda: len(twists) >= 10 and all(is_zero(t) for t in twists[-10:]),
                     what='10 zero Twists after the odometry stopped')
            print('FIGURE: deploy node: zero Twists %.2f s after the odometry stopped '
                  '(odom_timeout %.1f s)' % (time.monotonic() - stopped_at, ODOM_TIMEOUT))
            wait_for(lambda: states[-1][0] == DiagnosticStatus.WARN,
                     what='a WARN status while the odometry is stale')
            self.assertEqual(states[-1][1], 'standing: no fresh odometry on /robot/odom')
            self.assertGreater(float(states[-1][2]['odometry age [s]']), ODOM_TIMEOUT)

            count = len(twists)
            for k in range(NAN_ODOMS):
                odom_pub.publish(odometry(float('inf')) if k % 2
                                 else odometry(0.1, x=float('nan')))
            wait_for(lambda: drops and int(drops[-1]['dropped input']) == NAN_ODOMS,
                     what='/diagnostics counting %d dropped odometry messages' % NAN_ODOMS)
            self.assertIn('non-finite', drops[-1]['last reason'])
            wait_for(lambda: len(twists) >= count + 10, what='10 more Twists')
            self.assertTrue(all(is_zero(t) for t in twists[count:]),
                            'non-finite odometry moved the robot')

            source.running.set()
            wait_for(lambda: not is_zero(twists[-1]), what='moving again on fresh odometry')
            self.assertTrue(all(math.isfinite(v) for v in (twists[-1].linear.x,
                                                           twists[-1].angular.z)))
        finally:
            source.running.clear()
            signalled = time.monotonic()
            proc.send_signal(signal.SIGINT)
            code = proc.wait(timeout=TIMEOUT)
            exit_s = time.monotonic() - signalled
        print('FIGURE: deploy node: exit status %d %.2f s after SIGINT' % (code, exit_s))
        self.assertEqual(code, 0)
        self.assertLess(exit_s, 2.0)
        wait_for(lambda: is_zero(twists[-1]), what='a zero Twist last after SIGINT')


if __name__ == '__main__':
    rospy.init_node('test_deploy_node')
    rostest.rosrun('jetbot_rl', 'deploy_node', TestDeployNode)
