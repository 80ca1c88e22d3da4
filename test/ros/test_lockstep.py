#!/usr/bin/python3
"""600 lockstep steps through topics: every step id once and in order, time-outs at episode step
299 (EnvStep.step 299 and 598), auto-resets and final observations where they must be."""
import math
import unittest

import rospy
import rostest

from jetbot_rl_test.env_client import EnvClient, wait_for

NUM_ENVS = 3
STEPS = 600
TIMEOUT_STEPS = (299, 598)


def actions_for(step):
    # env 0 drives forward, env 1 turns, env 2 drives at a speed that changes with the step
    return [8.0, 8.0, 6.0, -6.0, 10.0 * math.sin(step / 40.0), 10.0]


class TestLockstep(unittest.TestCase):
    def test_600_steps(self):
        env = EnvClient()
        start = env.reset_srv(env_ids=[], seed=0)
        self.assertTrue(start.success, start.message)
        self.assertEqual(start.state.step, 0)
        wait_for(lambda: len(env.received()) == 1, what='the published reset state')
        self.assertEqual(env.received()[0].step, 0)
        obs_dim = start.state.obs_dim

        for step in range(STEPS):
            env.step_topic(step, actions_for(step))
        received = env.received()[1:]
        self.assertEqual([m.step for m in received], list(range(1, STEPS + 1)))

        previous = start.state
        for msg in received:
            s = msg.step
            self.assertEqual(msg.num_envs, NUM_ENVS)
            self.assertEqual(len(msg.observations), NUM_ENVS * obs_dim)
            self.assertEqual(len(msg.rewards), NUM_ENVS)
            self.assertEqual(list(msg.terminated), [0] * NUM_ENVS, 'step %d' % s)
            if s in TIMEOUT_STEPS:
                self.assertEqual(list(msg.truncated), [1] * NUM_ENVS, 'step %d' % s)
                self.assertEqual(list(msg.reset_env_ids), list(range(NUM_ENVS)), 'step %d' % s)
                self.assertEqual(list(msg.episode_steps), [0] * NUM_ENVS)
                self.assertEqual(len(msg.final_observations), NUM_ENVS * obs_dim)
                for e in range(NUM_ENVS):
                    final = msg.final_observations[e * obs_dim:(e + 1) * obs_dim]
                    before = previous.observations[e * obs_dim:(e + 1) * obs_dim]
                    # the final observation is the moving robot's, the reward its speed ...
                    self.assertGreater(math.sqrt(sum(v * v for v in final)), 0.02, 'env %d' % e)
                    self.assertAlmostEqual(msg.rewards[e], math.sqrt(sum(v * v for v in final)),
                                           places=4)
                    for f, b in zip(final, before):
                        self.assertLess(abs(f - b), 0.1, 'final observation of env %d' % e)
                    # ... and the observation is the first of the new episode: at rest
                    new = msg.observations[e * obs_dim:(e + 1) * obs_dim]
                    self.assertLess(max(abs(v) for v in new), 1e-3, 'env %d after reset' % e)
            else:
                self.assertEqual(list(msg.truncated), [0] * NUM_ENVS, 'step %d' % s)
                self.assertEqual(list(msg.reset_env_ids), [], 'step %d' % s)
                self.assertEqual(list(msg.final_observations), [], 'step %d' % s)
                expected = s if s < 299 else (s - 299 if s < 598 else s - 598)
                self.assertEqual(list(msg.episode_steps), [expected] * NUM_ENVS, 'step %d' % s)
            previous = msg
        # the robots really drove
        self.assertGreater(max(received[100].rewards), 0.05)


if __name__ == '__main__':
    rospy.init_node('test_lockstep')
    rostest.rosrun('jetbot_rl', 'test_lockstep', TestLockstep)
