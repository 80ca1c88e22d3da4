#!/usr/bin/python3
"""JetbotVecEnv over two env nodes: the batch is the concatenation, in list order, of what each
node gives alone with its own seed (seed + k * 2**32); nodes whose specs differ are refused."""
import unittest

import numpy as np
import rospy
import rostest

from jetbot_rl import NODE_SEED_STRIDE, JetbotVecEnv

A, B, C = '/env_a/jetbot_env', '/env_b/jetbot_env', '/env_c/jetbot_env'
NA, NB = 3, 2
STEPS = 305  # across the time-out at step 299
SEED = 11


def rollout(env, seed, actions):
    """Per step: obs, rewards, terminations, truncations, episode steps, final obs and mask."""
    obs, infos = env.reset(seed=seed)
    n = env.num_envs
    record = [(obs, infos['episode_steps'])]
    for a in actions:
        obs, rewards, terminations, truncations, infos = env.step(a)
        record.append((obs, rewards, terminations, truncations, infos['episode_steps'],
                       infos.get('final_obs', np.zeros((n, env.obs_dim), np.float32)),
                       infos.get('_final_obs', np.zeros(n, bool))))
    return record


class TestMultiNode(unittest.TestCase):
    def test_batch_is_the_concatenation_of_the_nodes(self):
        actions = np.random.default_rng(3).uniform(-20, 20, size=(STEPS, NA + NB, 2))
        with JetbotVecEnv(env_nodes=[A, B], timeout=30.0) as env:
            self.assertEqual(env.num_envs, NA + NB)
            self.assertEqual(env.nodes, [A, B])
            self.assertEqual(env.node_num_envs, [NA, NB])
            self.assertEqual(env.action_space.shape, (NA + NB, 2))
            both = rollout(env, SEED, actions)
            # partial resets reach the right node and env
            mask = np.zeros(NA + NB, dtype=bool)
            mask[[1, 4]] = True
            _, infos = env.reset(options={'reset_mask': mask})
            steps = infos['episode_steps']
            self.assertEqual(list(steps[mask]), [0, 0])
            self.assertTrue(np.all(steps[~mask] > 0))
            # set_command addresses batch env 4 = env 1 of env_b
            env.set_command(4, 0.0, 1.0)
            obs, _, _, _, _ = env.step(np.zeros((NA + NB, 2)))
            np.testing.assert_allclose(obs[4, :2], [0.0, 1.0], atol=0.01)
        with JetbotVecEnv(A, timeout=30.0) as env:
            alone_a = rollout(env, SEED, actions[:, :NA])
        with JetbotVecEnv(B, timeout=30.0) as env:
            alone_b = rollout(env, SEED + NODE_SEED_STRIDE, actions[:, NA:])
            wrong_seed_b = rollout(env, SEED, actions[:3, NA:])
        self.assertEqual(len(both), STEPS + 1)
        for t, (ab, a, b) in enumerate(zip(both, alone_a, alone_b)):
            for k, (x, y, z) in enumerate(zip(ab, a, b)):
                self.assertEqual(x.tobytes(), np.concatenate([y, z]).tobytes(),
                                 'step %d, array %d: the batch is not env_a + env_b' % (t, k))
        self.assertTrue(both[299][6].all(), 'the time-out at step 299 is not in the rollout')
        # node 1 is not reseeded with the plain seed: its commands differ from that
        self.assertFalse(np.array_equal(both[0][0][NA:], wrong_seed_b[0][0]))

    def test_mismatched_spec_refused(self):
        with self.assertRaisesRegex(ValueError, r"/env_c/jetbot_env has spec field task = "
                                    r"'velocity', but /env_a/jetbot_env has 'command'"):
            JetbotVecEnv([A, C], timeout=30.0)
        with self.assertRaisesRegex(ValueError, r"/env_a/jetbot_env has spec field task = "
                                    r"'command', but /env_c/jetbot_env has 'velocity'"):
            JetbotVecEnv([C, A], timeout=30.0)
        # the refused nodes are left usable
        with JetbotVecEnv(C, timeout=30.0) as env:
            env.reset()
            env.step(np.zeros((2, 2)))


if __name__ == '__main__':
    rospy.init_node('test_python_multi_node', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_python_multi_node', TestMultiNode)
