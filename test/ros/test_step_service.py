#!/usr/bin/python3
"""The ~step service gives bit-identical results to the wheel_targets topic for the same seed and
actions (command task, whose random commands depend on the seed), and publishes the same
EnvStep on ~env_step."""
import random
import struct
import unittest

import rospy
import rostest

from jetbot_rl_test.env_client import EnvClient, wait_for

STEPS = 320  # past one time-out (episode step 299), so auto-resets are compared too
SEED = 7


def bits(values):
    """The exact float32 bit patterns (so -0.0 != 0.0 and any last-bit difference shows)."""
    return [struct.unpack('<I', struct.pack('<f', v))[0] for v in values]


def fields(msg):
    return (bits(msg.observations), bits(msg.rewards), list(msg.terminated),
            list(msg.truncated), list(msg.episode_steps), list(msg.reset_env_ids),
            bits(msg.final_observations))


class TestStepService(unittest.TestCase):
    def test_service_matches_topic(self):
        env = EnvClient()
        n = env.spec.num_envs
        high = env.spec.action_high
        rng = random.Random(3)
        actions = [[rng.uniform(-1.2, 1.2) * high[i % 2] for i in range(2 * n)]
                   for _ in range(STEPS)]

        start = env.reset_srv(env_ids=[], seed=SEED)
        self.assertTrue(start.success, start.message)
        first = start.state.step
        by_topic = [env.step_topic(first + k, a) for k, a in enumerate(actions)]

        again = env.reset_srv(env_ids=[], seed=SEED)
        self.assertTrue(again.success, again.message)
        self.assertEqual(fields(again.state), fields(start.state))
        second = again.state.step
        self.assertEqual(second, first + STEPS)  # resets never advance the step
        count = len(env.received())
        by_service = []
        for k, a in enumerate(actions):
            res = env.step_service(second + k, a)
            self.assertTrue(res.success, res.message)
            self.assertEqual(res.state.step, second + k + 1)
            by_service.append(res.state)

        self.assertTrue(any(m.reset_env_ids for m in by_topic), 'no episode ended')
        self.assertGreater(max(max(abs(r) for r in m.rewards) for m in by_topic), 0.05)
        for k, (t, s) in enumerate(zip(by_topic, by_service)):
            self.assertEqual(fields(s), fields(t), 'step %d of the run differs' % k)
        # the service path published the same states on the topic, in order (a subscriber that
        # falls behind the calls may lose some: the node's publisher queue is bounded)
        last = second + STEPS
        wait_for(lambda: any(m.step == last for m in env.received()[count:]),
                 what='the EnvStep of the last service call')
        env_steps = [m for m in env.received()[count:] if m.step > second]
        ids = [m.step for m in env_steps]
        self.assertEqual(ids, sorted(set(ids)), 'EnvSteps out of order or repeated')
        self.assertGreater(len(env_steps), STEPS // 10)
        for m in env_steps:
            self.assertEqual(fields(m), fields(by_service[m.step - second - 1]), 'step %d' % m.step)
        # another seed draws other commands: the comparison above is not vacuous
        other = env.reset_srv(env_ids=[], seed=SEED + 1)
        self.assertTrue(other.success, other.message)
        self.assertNotEqual(bits(other.state.observations), bits(start.state.observations))


if __name__ == '__main__':
    rospy.init_node('test_step_service')
    rostest.rosrun('jetbot_rl', 'test_step_service', TestStepService)
