#!/usr/bin/python3
"""Every rejection case (stale step, future step, wrong length, NaN, inf), by topic and by ~step,
leaves the node alive and the state unchanged, and is counted in /diagnostics."""
import unittest

import rospy
import rostest

from jetbot_rl_test.env_client import EnvClient, wait_for

NUM_ENVS = 2
GOOD = [5.0, 4.0, -3.0, 6.0]
NAN = float('nan')
INF = float('inf')


class TestRejection(unittest.TestCase):
    def test_rejections(self):
        env = EnvClient()
        state = env.reset_srv(env_ids=[], seed=-1).state
        for _ in range(5):
            state = env.step_topic(state.step, GOOD)
        s = state.step
        # the cases, each with a text the reason must contain
        cases = [
            (s - 1, GOOD, 'stale step %d' % (s - 1)),
            (s + 1, GOOD, 'future step %d' % (s + 1)),
            (s, GOOD[:3], 'expected 4 values'),
            (s, GOOD + [1.0], 'expected 4 values'),
            (s, [1.0, NAN, 1.0, 1.0], 'not finite'),
            (s, [1.0, 1.0, -INF, 1.0], 'not finite'),
            (s, [], 'got 0'),
        ]
        rejected = 0
        # --- by topic: none steps; the next valid message for step s is the one that answers ---
        count = len(env.received())
        for step, velocities, _ in cases:
            env.publish(step, velocities)
        rejected += len(cases)
        status = env.wait_diagnostics(lambda d: int(d['rejected messages']) >= rejected,
                                      'diagnostics counting %d rejections' % rejected)
        self.assertEqual(int(status['rejected messages']), rejected)
        self.assertIn('got 0', status['last rejection reason'])
        self.assertEqual(int(status['current step']), s)
        self.assertEqual(len(env.received()), count, 'a rejected message published a step')
        current = env.current()  # a future-step call: rejected, answered with the state
        rejected += 1
        self.assertEqual(current.step, s)
        self.assertEqual(list(current.observations), list(state.observations))
        self.assertEqual(list(current.episode_steps), list(state.episode_steps))

        # --- by service: each answered with success false, the reason and the unchanged state ---
        for step, velocities, text in cases:
            res = env.step_service(step, velocities)
            rejected += 1
            self.assertFalse(res.success, text)
            self.assertIn(text, res.message)
            self.assertEqual(res.state.step, s)
            self.assertEqual(list(res.state.observations), list(state.observations))
            self.assertEqual(list(res.state.episode_steps), list(state.episode_steps))
        status = env.wait_diagnostics(lambda d: int(d['rejected messages']) >= rejected,
                                      'diagnostics counting %d rejections' % rejected)
        self.assertEqual(int(status['rejected messages']), rejected)
        self.assertIn('got 0', status['last rejection reason'])

        # --- still alive, and the state went on from where it was ---
        nxt = env.step_topic(s, GOOD)
        self.assertEqual(nxt.step, s + 1)
        self.assertEqual(list(nxt.episode_steps), [e + 1 for e in state.episode_steps])
        res = env.step_service(s + 1, GOOD)
        self.assertTrue(res.success, res.message)
        self.assertEqual(res.state.step, s + 2)
        wait_for(lambda: len(env.received()) >= count + 2, what='the EnvStep of the service call')
        self.assertEqual([m.step for m in env.received()[count:]], [s + 1, s + 2])


if __name__ == '__main__':
    rospy.init_node('test_rejection')
    rostest.rosrun('jetbot_rl', 'test_rejection', TestRejection)
