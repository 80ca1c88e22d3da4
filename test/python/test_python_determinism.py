#!/usr/bin/python3
"""JetbotVecEnv determinism (same seed and actions => bit-identical rollouts), partial resets and
set_command, on the command task (4 envs)."""
import unittest

import numpy as np
import rospy
import rostest

from jetbot_rl import JetbotVecEnv
from jetbot_rl.msg import EnvSpec
from jetbot_rl_test.py_test_util import spec_bounds

NUM_ENVS = 4
STEPS = 310  # across the time-out at step 299


def actions_for(seed):
    rng = np.random.default_rng(seed)
    return rng.uniform(-20.0, 20.0, size=(STEPS, NUM_ENVS, 2)).astype(np.float32)


def rollout(env, seed, actions):
    """Every array the env returns, in order."""
    obs, infos = env.reset(seed=seed)
    record = [obs, infos['episode_steps']]
    for a in actions:
        obs, rewards, terminations, truncations, infos = env.step(a)
        record += [obs, rewards, terminations, truncations, infos['episode_steps']]
        if 'final_obs' in infos:
            record += [infos['final_obs'], infos['_final_obs']]
    return record


# The node's spec, read before the tests are defined: whether it sends observation bounds decides
# whether test_command_observation_bounds runs.
rospy.init_node('test_python_determinism', disable_signals=True)
NO_BOUNDS = len(rospy.wait_for_message('/jetbot_env/spec', EnvSpec, 60.0).observation_low) == 0


class TestDeterminism(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = JetbotVecEnv('/jetbot_env', timeout=30.0)

    def test_same_seed_bit_identical(self):
        actions = actions_for(1)
        first = rollout(self.env, 5, actions)
        second = rollout(self.env, 5, actions)
        self.assertEqual(len(first), len(second))
        self.assertGreater(len(first), 5 * STEPS)  # the time-out's final_obs are in
        for k, (a, b) in enumerate(zip(first, second)):
            self.assertEqual(a.dtype, b.dtype)
            self.assertEqual(a.tobytes(), b.tobytes(), 'array %d differs' % k)
        # another seed: other commands, other observations from the first one on
        other = rollout(self.env, 6, actions[:3])
        self.assertFalse(np.array_equal(other[0], first[0]))

    def test_partial_reset(self):
        env = self.env
        env.reset(seed=2)
        for _ in range(10):
            obs, _, _, _, infos = env.step(np.full((NUM_ENVS, 2), 10.0))
        mask = np.array([True, False, False, True])
        new_obs, infos = env.reset(options={'reset_mask': mask})
        np.testing.assert_array_equal(infos['episode_steps'], [0, 10, 10, 0])
        np.testing.assert_array_equal(new_obs[~mask], obs[~mask])  # the others keep their state
        self.assertFalse(np.array_equal(new_obs[mask], obs[mask]))
        obs, _, _, _, infos = env.step(np.full((NUM_ENVS, 2), 10.0))
        np.testing.assert_array_equal(infos['episode_steps'], [1, 11, 11, 1])
        # a seeded partial reset is reproducible: the same commands again
        a, _ = env.reset(seed=9, options={'reset_mask': mask})
        b, _ = env.reset(seed=9, options={'reset_mask': mask})
        np.testing.assert_array_equal(a[mask], b[mask])
        # nothing to reset: the current state
        c, infos = env.reset(options={'reset_mask': np.zeros(NUM_ENVS, dtype=bool)})
        np.testing.assert_array_equal(c, b)

    def test_observation_space_is_the_spec(self):
        low, high = spec_bounds(self.env.specs[0])
        np.testing.assert_array_equal(self.env.single_observation_space.low, low)
        np.testing.assert_array_equal(self.env.single_observation_space.high, high)
        np.testing.assert_array_equal(self.env.observation_space.low, np.tile(low, (NUM_ENVS, 1)))

    @unittest.skipIf(NO_BOUNDS, 'the node sends no observation bounds (EnvSpec.observation_low '
                     'empty): runs once the C++ side fills them')
    def test_command_observation_bounds(self):
        """Once the node fills them: forward_dot_command and forward_cross_command_z (a cosine
        and a sine) in [-1, 1], lin_vel_b_x unbounded."""
        np.testing.assert_array_equal(self.env.single_observation_space.low, [-1.0, -1.0, -np.inf])
        np.testing.assert_array_equal(self.env.single_observation_space.high, [1.0, 1.0, np.inf])

    def test_set_command(self):
        env = self.env
        env.reset(seed=0)
        env.set_command(2, 0.0, 3.0)  # +y: to the left of a robot facing +x
        env.set_command(3, -1.0, 0.0)  # behind it
        obs, _, _, _, _ = env.step(np.zeros((NUM_ENVS, 2)))
        self.assertEqual(env.observation_names[:2],
                         ['forward_dot_command', 'forward_cross_command_z'])
        np.testing.assert_allclose(obs[2, :2], [0.0, 1.0], atol=0.01)
        np.testing.assert_allclose(obs[3, :2], [-1.0, 0.0], atol=0.01)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_python_determinism', TestDeterminism)
