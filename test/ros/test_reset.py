#!/usr/bin/python3
"""~reset of selected envs: they restart, the others are unchanged, the step does not advance, the
new state is published; invalid or repeated ids reset nothing."""
import unittest

import rospy
import rostest

from jetbot_rl_test.env_client import EnvClient, wait_for

NUM_ENVS = 4


def env_slice(values, e, dim):
    return list(values[e * dim:(e + 1) * dim])


class TestReset(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = EnvClient()

    def setUp(self):
        self.dim = self.env.spec.obs_dim
        state = self.env.reset_srv(env_ids=[], seed=-1).state
        # drive every env for a while so that a reset is visible
        step = state.step
        for _ in range(40):
            state = self.env.step_topic(step, [9.0, 7.0] * NUM_ENVS)
            step = state.step
        self.moving = state
        for e in range(NUM_ENVS):
            self.assertGreater(max(abs(v) for v in env_slice(state.observations, e, self.dim)),
                               0.02)

    def test_reset_selected(self):
        before = self.moving
        count = len(self.env.received())
        res = self.env.reset_srv(env_ids=[3, 1], seed=11)
        self.assertTrue(res.success, res.message)
        after = res.state
        self.assertEqual(after.step, before.step)  # not advanced
        for e in range(NUM_ENVS):
            obs = env_slice(after.observations, e, self.dim)
            if e in (1, 3):
                self.assertEqual(after.episode_steps[e], 0)
                self.assertLess(max(abs(v) for v in obs), 1e-3, 'env %d is at rest' % e)
            else:
                self.assertEqual(after.episode_steps[e], before.episode_steps[e])
                self.assertEqual(obs, env_slice(before.observations, e, self.dim),
                                 'env %d changed' % e)
        self.assertEqual(list(after.reset_env_ids), [])
        self.assertEqual(list(after.truncated), [0] * NUM_ENVS)
        # the new state was published, with the same step
        wait_for(lambda: len(self.env.received()) > count, what='the published reset state')
        published = self.env.received()[count]
        self.assertEqual(published.step, before.step)
        self.assertEqual(list(published.observations), list(after.observations))
        self.assertEqual(list(published.episode_steps), list(after.episode_steps))
        # and the learner goes on answering the same step
        nxt = self.env.step_topic(before.step, [1.0, 1.0] * NUM_ENVS)
        self.assertEqual(list(nxt.episode_steps[1:4:2]), [1, 1])

    def test_reset_all(self):
        res = self.env.reset_srv(env_ids=[], seed=-1)
        self.assertTrue(res.success, res.message)
        self.assertEqual(res.state.step, self.moving.step)
        self.assertEqual(list(res.state.episode_steps), [0] * NUM_ENVS)
        self.assertLess(max(abs(v) for v in res.state.observations), 1e-3)

    def check_rejected(self, env_ids, text):
        before = self.env.current()
        res = self.env.reset_srv(env_ids=env_ids, seed=5)
        self.assertFalse(res.success)
        self.assertIn(text, res.message)
        self.assertEqual(res.state.step, before.step)
        after = self.env.current()
        self.assertEqual(list(after.observations), list(before.observations))
        self.assertEqual(list(after.episode_steps), list(before.episode_steps))
        self.assertGreater(min(after.episode_steps), 0)  # nothing was reset

    def test_out_of_range_id(self):
        self.check_rejected([0, NUM_ENVS], str(NUM_ENVS))

    def test_repeated_id(self):
        self.check_rejected([2, 0, 2], 'twice')


if __name__ == '__main__':
    rospy.init_node('test_reset')
    rostest.rosrun('jetbot_rl', 'test_reset', TestReset)
