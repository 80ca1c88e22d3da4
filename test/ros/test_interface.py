#!/usr/bin/python3
"""jetbot_env advertises its topics and services and latches ~spec with the right contents."""
import unittest

import rosgraph
import rospy
import rostest

from jetbot_rl.msg import EnvSpec
from jetbot_rl.srv import Reset, SetCommand
from jetbot_rl_test.env_client import UNREPORTED_RECHECK, NODE, TIMEOUT, wait_for


class TestInterface(unittest.TestCase):
    def test_topics_and_services(self):
        master = rosgraph.Master('/test_interface')

        def advertised():
            pubs, subs, srvs = master.getSystemState()
            pubs = {t: n for t, n in pubs}
            subs = {t: n for t, n in subs}
            srvs = {s: n for s, n in srvs}
            return (NODE in pubs.get(NODE + '/env_step', []) and
                    NODE in pubs.get(NODE + '/spec', []) and
                    NODE in pubs.get('/clock', []) and
                    NODE in pubs.get('/tf', []) and
                    NODE in pubs.get('/diagnostics', []) and
                    NODE in subs.get(NODE + '/wheel_targets', []) and
                    NODE in pubs.get(NODE + '/markers', []) and
                    NODE in srvs.get(NODE + '/set_command', []) and
                    NODE in srvs.get(NODE + '/get_randomization', []) and
                    NODE in srvs.get(NODE + '/step', []) and
                    NODE in srvs.get(NODE + '/reset', []))
        wait_for(advertised, what='every topic and service of ' + NODE,
                 recheck=UNREPORTED_RECHECK)
        types = dict(master.getTopicTypes())
        self.assertEqual(types[NODE + '/env_step'], 'jetbot_rl/EnvStep')
        self.assertEqual(types[NODE + '/spec'], 'jetbot_rl/EnvSpec')
        self.assertEqual(types[NODE + '/wheel_targets'], 'jetbot_rl/WheelTargets')
        self.assertEqual(types['/clock'], 'rosgraph_msgs/Clock')
        self.assertEqual(types[NODE + '/markers'], 'visualization_msgs/MarkerArray')
        self.assertEqual(types['/diagnostics'], 'diagnostic_msgs/DiagnosticArray')
        rospy.wait_for_service(NODE + '/step', TIMEOUT)
        rospy.wait_for_service(NODE + '/reset', TIMEOUT)

    def test_spec_latched(self):
        # Subscribing long after the node published it: only a latched message arrives.
        spec = rospy.wait_for_message(NODE + '/spec', EnvSpec, TIMEOUT)
        self.assertEqual(spec.num_envs, 5)
        self.assertEqual(spec.obs_dim, 3)
        self.assertEqual(spec.action_dim, 2)
        self.assertEqual(len(spec.action_low), 2)
        self.assertEqual(len(spec.action_high), 2)
        for low, high in zip(spec.action_low, spec.action_high):
            self.assertLess(low, 0.0)
            self.assertEqual(low, -high)
        self.assertAlmostEqual(spec.control_dt, 1.0 / 60.0, places=12)
        self.assertEqual(spec.max_episode_length, 300)
        self.assertEqual(spec.task, 'velocity')
        self.assertEqual(spec.observation_names, ['lin_vel_b_x', 'lin_vel_b_y', 'lin_vel_b_z'])
        self.assertEqual(spec.action_names, ['left_wheel_joint', 'right_wheel_joint'])
        self.assertEqual((list(spec.scan_beam_angles), list(spec.scan_range)), ([], []))

    def test_velocity_task_has_no_command(self):
        rospy.wait_for_service(NODE + '/set_command', TIMEOUT)
        res = rospy.ServiceProxy(NODE + '/set_command', SetCommand)(env_id=0, x=1.0, y=0.0)
        self.assertFalse(res.success)
        self.assertIn("task 'velocity' has no command", res.message)
        self.assertIn('parameter task', res.message)

    def test_reset_reports_state(self):
        rospy.wait_for_service(NODE + '/reset', TIMEOUT)  # tests run in name order: this one first
        res = rospy.ServiceProxy(NODE + '/reset', Reset)(env_ids=[], seed=-1)
        self.assertTrue(res.success, res.message)
        self.assertEqual(res.state.num_envs, 5)
        self.assertEqual(res.state.obs_dim, 3)
        self.assertEqual(len(res.state.observations), 15)
        self.assertEqual(list(res.state.episode_steps), [0] * 5)


if __name__ == '__main__':
    rospy.init_node('test_interface')
    rostest.rosrun('jetbot_rl', 'test_interface', TestInterface)
