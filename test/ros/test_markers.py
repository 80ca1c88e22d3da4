#!/usr/bin/python3
"""Task `command`: ~markers carries a body and two arrows (forward, command) per visualised env, and
~set_command steers an env's command: its arrow, its observation, and (held) across resets."""
import math
import threading
import unittest

import rospy
import rostest
from visualization_msgs.msg import Marker, MarkerArray

from jetbot_rl.srv import SetCommand
from jetbot_rl_test.env_client import NODE, TIMEOUT, EnvClient

VISUALISED = 3  # tf_envs in markers.test


def yaw(orientation):
    return 2.0 * math.atan2(orientation.z, orientation.w)


class TestMarkers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = EnvClient()
        cls.lock = threading.Lock()
        cls.arrays = []
        cls.sub = rospy.Subscriber(NODE + '/markers', MarkerArray, cls._on_markers)
        rospy.wait_for_service(NODE + '/set_command', TIMEOUT)
        cls.set_command = rospy.ServiceProxy(NODE + '/set_command', SetCommand)

    @classmethod
    def _on_markers(cls, msg):
        with cls.lock:
            cls.arrays.append(msg)

    def newest_markers(self, after_stamp):
        """The first MarkerArray stamped after `after_stamp`, stepping the env until one comes."""
        def arrived():
            with self.lock:
                return any(a.markers[0].header.stamp > after_stamp for a in self.arrays)
        while not arrived():
            state = self.client.current()
            self.client.step_topic(state.step, [0.0] * (2 * state.num_envs))
            if rospy.is_shutdown():
                self.fail('shut down')
        with self.lock:
            return next(a for a in self.arrays if a.markers[0].header.stamp > after_stamp)

    def test_two_arrows_and_a_body_per_visualised_env(self):
        array = self.newest_markers(rospy.Time(0))
        arrows = [m for m in array.markers if m.type == Marker.ARROW]
        bodies = [m for m in array.markers if m.type == Marker.CUBE]
        self.assertEqual(sorted((m.ns, m.id) for m in arrows),
                         sorted([('command', e) for e in range(VISUALISED)] +
                                [('forward', e) for e in range(VISUALISED)]))
        self.assertEqual(sorted(m.id for m in bodies), list(range(VISUALISED)))
        for m in array.markers:
            self.assertEqual(m.header.frame_id, 'world')
            self.assertEqual(m.action, Marker.ADD)
        # Each env's colour differs from the others'.
        colours = {(round(b.color.r, 3), round(b.color.g, 3), round(b.color.b, 3)) for b in bodies}
        self.assertEqual(len(colours), VISUALISED)

    def test_set_command_turns_the_arrow_and_the_observation(self):
        res = self.set_command(env_id=1, x=0.0, y=2.0, hold=False)
        self.assertTrue(res.success, res.message)
        state = self.client.current()
        step = self.client.step_topic(state.step, [0.0] * (2 * state.num_envs))
        obs = step.observations[1 * step.obs_dim:2 * step.obs_dim]
        # The robot still faces +x; the command is +y: 90 degrees to its left.
        self.assertAlmostEqual(obs[0], 0.0, places=2)
        self.assertAlmostEqual(obs[1], 1.0, places=2)
        array = self.newest_markers(step.header.stamp - rospy.Duration(1e-6))
        command = next(m for m in array.markers if m.ns == 'command' and m.id == 1)
        self.assertAlmostEqual(yaw(command.pose.orientation), math.pi / 2, places=3)

    def test_a_held_command_survives_a_reset(self):
        self.assertTrue(self.set_command(env_id=2, x=-1.0, y=0.0, hold=True).success)
        self.assertTrue(self.client.reset_srv(env_ids=[2], seed=-1).success)
        state = self.client.current()
        step = self.client.step_topic(state.step, [0.0] * (2 * state.num_envs))
        obs = step.observations[2 * step.obs_dim:3 * step.obs_dim]
        self.assertAlmostEqual(obs[0], -1.0, places=2)  # facing away from the command
        self.assertTrue(self.set_command(env_id=2, x=1.0, y=0.0, hold=False).success)

    def test_bad_commands_are_refused(self):
        res = self.set_command(env_id=5, x=1.0, y=0.0, hold=False)
        self.assertFalse(res.success)
        self.assertIn('env 5', res.message)
        res = self.set_command(env_id=0, x=0.0, y=0.0, hold=False)
        self.assertFalse(res.success)
        self.assertIn('non-zero', res.message)


if __name__ == '__main__':
    rospy.init_node('test_markers')
    rostest.rosrun('jetbot_rl', 'markers', TestMarkers)
