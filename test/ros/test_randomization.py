#!/usr/bin/python3
"""~get_randomization: the values every env drew at its last reset, within the configured ranges,
different per env, the same again after a ~reset with the same seed, new after one without; the
drawn initial speed shows in the observations; bad ids are refused."""
import unittest

import rospy
import rostest

from jetbot_rl.srv import GetRandomization
from jetbot_rl_test.env_client import NODE, TIMEOUT, EnvClient

NUM_ENVS = 8


class TestRandomization(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = EnvClient()
        rospy.wait_for_service(NODE + '/get_randomization', TIMEOUT)
        cls.get = rospy.ServiceProxy(NODE + '/get_randomization', GetRandomization)

    def values(self, env_ids=()):
        res = self.get(env_ids=list(env_ids))
        self.assertTrue(res.success, res.message)
        return res.randomization

    def drawn(self, r):
        """Every drawn value of every env, for comparisons."""
        return (list(r.mass_scale), list(r.wheel_friction), list(r.initial_yaw),
                list(r.action_delay_steps), list(r.motor_trim))

    def test_values_in_range_per_env(self):
        r = self.values()
        self.assertEqual(list(r.env_ids), list(range(NUM_ENVS)))
        self.assertEqual(r.num_dofs, 2)
        self.assertEqual(len(r.motor_trim), 2 * NUM_ENVS)
        self.assertEqual(len(r.motor_dead_zone), 2 * NUM_ENVS)
        for e in range(NUM_ENVS):
            self.assertTrue(0.8 <= r.mass_scale[e] <= 1.25, r.mass_scale)
            self.assertTrue(0.7 <= r.wheel_friction[e] <= 1.0, r.wheel_friction)
            self.assertTrue(-3.0 <= r.initial_yaw[e] <= 3.0, r.initial_yaw)
            self.assertEqual(r.initial_speed[e], 0.2)
            self.assertIn(r.action_delay_steps[e], (0, 1, 2))
            self.assertEqual(r.drive_gain_scale[e], 1.0)  # not randomised
            self.assertEqual(r.motor_dead_zone[2 * e], 0.0)
            for trim in r.motor_trim[2 * e:2 * e + 2]:
                self.assertTrue(0.9 <= trim <= 1.1, r.motor_trim)
        self.assertEqual(len(set(r.mass_scale)), NUM_ENVS, 'envs drew the same mass')
        # Selected envs, in the order asked.
        some = self.values([5, 2])
        self.assertEqual(list(some.env_ids), [5, 2])
        self.assertEqual(list(some.mass_scale), [r.mass_scale[5], r.mass_scale[2]])
        self.assertEqual(list(some.motor_trim), list(r.motor_trim[10:12] + r.motor_trim[4:6]))

    def test_reset_redraws_and_seed_repeats(self):
        state = self.env.reset_srv(env_ids=[], seed=11).state
        first = self.values()
        self.assertEqual(first.step, state.step)
        self.assertEqual(first.header.stamp, state.header.stamp)
        # The drawn initial speed (0.2 m/s forward, noise 0.001) is in the first observation.
        dim = self.env.spec.obs_dim
        for e in range(NUM_ENVS):
            self.assertAlmostEqual(state.observations[e * dim], 0.2, delta=0.01)
        self.env.reset_srv(env_ids=[], seed=-1)
        self.assertNotEqual(self.drawn(self.values()), self.drawn(first))
        self.env.reset_srv(env_ids=[], seed=11)
        self.assertEqual(self.drawn(self.values()), self.drawn(first))
        # A reset of one env redraws only its values.
        self.env.reset_srv(env_ids=[6], seed=-1)
        after = self.values()
        for e in range(NUM_ENVS):
            same = after.mass_scale[e] == first.mass_scale[e]
            self.assertEqual(same, e != 6, 'env %d' % e)

    def test_bad_ids_refused(self):
        res = self.get(env_ids=[NUM_ENVS])
        self.assertFalse(res.success)
        self.assertIn('out of range', res.message)
        res = self.get(env_ids=[1, 1])
        self.assertFalse(res.success)
        self.assertIn('listed twice', res.message)


if __name__ == '__main__':
    rospy.init_node('test_randomization')
    rostest.rosrun('jetbot_rl', 'test_randomization', TestRandomization)
