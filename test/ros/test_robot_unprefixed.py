#!/usr/bin/python3
"""env_prefix false, publish_link_tf false, the tribot, and robot_state_publisher run with no
parameters: /cmd_vel drives the robot, /odom has frame odom and child frame base_footprint, and
one tf tree world -> odom -> base_footprint (the node) -> base_link -> wheel_left_link
(robot_state_publisher) agrees with odom; the node sends no link frames of its own."""
import math
import threading
import unittest

import rospy
import rostest
import tf2_ros
from tf2_msgs.msg import TFMessage

from jetbot_rl.msg import EnvSpec
from jetbot_rl_test.env_client import NODE, TIMEOUT, EventList, wait_for
from jetbot_rl_test.robot_view_client import RobotView, twist


class TestRobotUnprefixed(unittest.TestCase):
    def test_standard_names_and_one_tree_with_robot_state_publisher(self):
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)  # noqa: F841 (keeps listening)
        senders = {}  # (parent, child) -> callers that sent it on /tf
        lock = threading.Lock()
        seen = EventList()

        def on_tf(msg):
            caller = msg._connection_header['callerid']
            with lock:
                for t in msg.transforms:
                    senders.setdefault((t.header.frame_id, t.child_frame_id), set()).add(caller)
            seen.append(caller)
        rospy.Subscriber('/tf', TFMessage, on_tf, queue_size=1000)

        view = RobotView('/')
        spec = rospy.wait_for_message(NODE + '/spec', EnvSpec, TIMEOUT)
        topics = [name for name, _ in rospy.get_published_topics()]
        for topic in ('/odom', '/joint_states'):
            self.assertIn(topic, topics)
        self.assertFalse([t for t in topics if t.startswith('/env_0/')], topics)
        self.assertEqual(view.odom[-1].header.frame_id, 'odom')
        self.assertEqual(view.odom[-1].child_frame_id, 'base_footprint')
        self.assertEqual(sorted(view.joints[-1].name), ['wheel_left_joint', 'wheel_right_joint'])

        v = 0.5 * spec.action_high[0] * spec.wheel_radius
        view.drive(twist(v, 0.5), 2.0)  # a gentle arc
        last = view.odom[-1]

        # the whole chain is known, from world to a wheel
        wait_for(lambda: buffer.can_transform('world', 'wheel_left_link', last.header.stamp),
                 what='world -> wheel_left_link', recheck=0.05)
        # odom -> base_footprint is the odometry
        t = buffer.lookup_transform('odom', 'base_footprint', last.header.stamp).transform
        p = last.pose.pose.position
        self.assertLess(math.hypot(t.translation.x - p.x, t.translation.y - p.y), 1e-6)
        self.assertGreater(math.hypot(p.x, p.y), 0.1, 'the robot did not move')
        # world -> odom is the env origin (one env: world's origin)
        t = buffer.lookup_transform('world', 'odom', rospy.Time(0)).transform
        self.assertEqual((t.translation.x, t.translation.y, t.translation.z), (0.0, 0.0, 0.0))
        # base_link -> wheel_left_link is the URDF joint (0, 0.08, 0.023), from joint_states
        t = buffer.lookup_transform('base_link', 'wheel_left_link', last.header.stamp).transform
        self.assertAlmostEqual(t.translation.y, 0.08, places=6)
        self.assertAlmostEqual(t.translation.z, 0.023, places=6)

        # who sent what: the node only odom -> base_footprint, robot_state_publisher the links
        with lock:
            node_frames = {k for k, callers in senders.items() if NODE in callers}
            rsp_frames = {k for k, callers in senders.items() if '/state_publisher' in callers}
        self.assertEqual(node_frames, {('odom', 'base_footprint')})
        self.assertIn(('base_link', 'wheel_left_link'), rsp_frames)
        self.assertIn(('base_link', 'wheel_right_link'), rsp_frames)


if __name__ == '__main__':
    rospy.init_node('test_robot_unprefixed')
    rostest.rosrun('jetbot_rl', 'test_robot_unprefixed', TestRobotUnprefixed)
