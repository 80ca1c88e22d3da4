#!/usr/bin/python3
"""JetbotVecEnv's errors against a real node (2 envs, velocity task): every bad input raises
ValueError naming the env and value and sends nothing; a step the node rejects raises
EnvRejectedError with the node's reason; Ctrl-C during a step leaves the env usable."""
import re
import signal
import time
import unittest

import numpy as np
import rospy
import rostest

from jetbot_rl import EnvRejectedError, JetbotVecEnv
from jetbot_rl.msg import EnvStep, WheelTargets
from jetbot_rl.srv import Step
from jetbot_rl.process_info import node_pid
from jetbot_rl_test.py_test_util import Diagnostics, EventList, interrupt_main_after, resume, stop

NODE = '/jetbot_env'
GOOD = np.full((2, 2), 5.0, dtype=np.float32)


class TestBadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = JetbotVecEnv(NODE, timeout=10.0)
        cls.diagnostics = Diagnostics()

    def setUp(self):
        self.env.reset()

    def applied_and_rejected(self, at_least_steps):
        """(steps applied, rejected messages) from a diagnostics report after that many steps."""
        status = self.diagnostics.wait(lambda d: int(d['steps applied']) >= at_least_steps,
                                       'diagnostics with %d steps applied' % at_least_steps)
        return int(status['steps applied']), int(status['rejected messages'])

    def test_bad_actions_send_nothing(self):
        env = self.env
        env.step(GOOD)
        applied, rejected = self.applied_and_rejected(1)
        cases = [
            (np.zeros((3, 2)), r"shape \(3, 2\), expected \(num_envs, action_dim\) = \(2, 2\) "
                               r"for /jetbot_env"),
            (np.zeros(4), r'shape \(4,\)'),
            (np.zeros((2, 3)), r'shape \(2, 3\)'),
            ([[1.0, 2.0], [3.0]], 'not numbers'),
            ([['a', 'b'], ['c', 'd']], 'not numbers'),
            ([[1.0, 2.0], [float('nan'), 0.0]],
             r'actions\[1, 0\] = nan \(env 1: /jetbot_env env 1, left_wheel_joint\) is not a '
             r'finite float32; nothing was sent'),
            ([[1.0, -float('inf')], [0.0, 0.0]], r'actions\[0, 1\] = -inf \(env 0'),
            (np.array([[0.0, 0.0], [0.0, 1e39]]), r'actions\[1, 1\] = 1e\+39 \(env 1.*'
                                                  r'right_wheel_joint'),
        ]
        for actions, pattern in cases:
            with self.assertRaisesRegex(ValueError, pattern):
                env.step(actions)
        # still in step with the node: the next good step is answered
        obs, _, _, _, infos = env.step(GOOD)
        np.testing.assert_array_equal(infos['episode_steps'], [2, 2])
        # and the node saw no message between the two good steps
        now_applied, now_rejected = self.applied_and_rejected(applied + 1)
        self.assertEqual(now_rejected, rejected, 'a bad input reached the node')

    def test_bad_reset_arguments(self):
        env = self.env
        for seed in (-1, 1.5, True, '3', 2 ** 63):
            with self.assertRaisesRegex(ValueError, 'seed'):
                env.reset(seed=seed)
        for options in ({'foo': 1}, [1], {'reset_mask': [1, 0]},
                        {'reset_mask': np.ones(3, dtype=bool)}):
            with self.assertRaisesRegex(ValueError, 'reset_mask|options'):
                env.reset(options=options)
        env.reset(seed=np.int64(3))  # numpy integers are ints
        env.step(GOOD)

    def test_bad_commands(self):
        env = self.env
        for bad_env in (2, -1, 1.0, True):
            with self.assertRaisesRegex(ValueError, r'set_command: env = .* is not in \[0, 2\)'):
                env.set_command(bad_env, 1.0, 0.0)
        with self.assertRaisesRegex(ValueError, r'x = nan for env 1 \(/jetbot_env env 1\)'):
            env.set_command(1, float('nan'), 0.0)
        # the node's own reason: this env runs the velocity task
        with self.assertRaisesRegex(EnvRejectedError, "/jetbot_env rejected the request: task "
                                                      "'velocity' has no command"):
            env.set_command(1, 1.0, 0.0)

    def test_bad_constructor_arguments(self):
        for env_nodes in ([], '', [NODE, 3]):
            with self.assertRaisesRegex(ValueError, 'env_nodes must be an env node name'):
                JetbotVecEnv(env_nodes)
            with self.assertRaisesRegex(ValueError, 'env_nodes must be an env node name'):
                JetbotVecEnv(env_nodes=env_nodes)
        # the keyword's old name is refused, naming the new one, before any node is looked up
        with self.assertRaisesRegex(TypeError, '^JetbotVecEnv: envs was renamed env_nodes$'):
            JetbotVecEnv(envs=NODE)
        with self.assertRaisesRegex(TypeError, 'envs was renamed env_nodes'):
            JetbotVecEnv(envs=[NODE], timeout=1.0)
        with self.assertRaisesRegex(TypeError, "unexpected keyword argument 'node'"):
            JetbotVecEnv(node=NODE)
        for timeout in (0, -1.0, float('inf'), 'x'):
            with self.assertRaisesRegex(ValueError, 'timeout'):
                JetbotVecEnv(NODE, timeout=timeout)
        for flag in ('yes', 1, None, 1.0):
            with self.assertRaisesRegex(TypeError, "^JetbotVecEnv: normalize_actions must be True "
                                                   "or False, got %s$" % re.escape(repr(flag))):
                JetbotVecEnv(NODE, normalize_actions=flag)
        with self.assertRaisesRegex(ValueError, 'node /jetbot_env is listed twice'):
            JetbotVecEnv([NODE, 'jetbot_env'])  # relative names resolve in our namespace, /
        start = time.monotonic()
        with self.assertRaisesRegex(TimeoutError, r'/no_such_env: no latched spec on '
                                                  r'/no_such_env/spec within 1.0 s: is '
                                                  r'jetbot_env running there'):
            JetbotVecEnv('/no_such_env', timeout=1.0)
        self.assertLess(time.monotonic() - start, 5.0)

    def test_step_rejected_by_the_node(self):
        env = self.env
        env.step(GOOD)
        # another client steps the node: our next targets are stale, and the node says so
        other = rospy.ServiceProxy(NODE + '/step', Step)
        current = other(actions=WheelTargets(step=2 ** 64 - 1)).state.step  # a rejected probe
        seen = EventList()
        # Callbacks of one topic run in the order they were added, on the connection our client
        # shares: once this one has the other client's EnvStep, so has the client.
        sub = rospy.Subscriber(NODE + '/env_step', EnvStep, lambda m: seen.append(m.step))
        res = other(actions=WheelTargets(step=current, velocities=GOOD.ravel().tolist()))
        self.assertTrue(res.success, res.message)
        seen.wait_for(lambda: current + 1 in seen, 'EnvStep %d' % (current + 1))
        sub.unregister()
        with self.assertRaisesRegex(
                EnvRejectedError, r'/jetbot_env rejected the request: stale step %d: the current '
                r'step is %d \(is another client stepping /jetbot_env' % (current, current + 1)):
            env.step(GOOD)
        with self.assertRaisesRegex(RuntimeError, r'call reset\(\) to re-synchronise'):
            env.step(GOOD)
        obs, infos = env.reset()
        obs, _, _, _, infos = env.step(GOOD)
        np.testing.assert_array_equal(infos['episode_steps'], [1, 1])

    def test_ctrl_c_leaves_the_env_usable(self):
        env = self.env
        env.step(GOOD)
        pid = node_pid(NODE)
        # default SIGINT handling (rospy's are disabled): Ctrl-C raises KeyboardInterrupt
        signal.signal(signal.SIGINT, signal.default_int_handler)
        stop(pid)  # the node cannot answer: step() waits, and Ctrl-C comes while it waits
        try:
            timer = interrupt_main_after(0.2)
            start = time.monotonic()
            with self.assertRaises(KeyboardInterrupt):
                env.step(GOOD)
            self.assertLess(time.monotonic() - start, 2.0)
            timer.join()
        finally:
            resume(pid)
        with self.assertRaisesRegex(RuntimeError, r'call reset\(\)'):
            env.step(GOOD)
        obs, infos = env.reset()
        for k in range(1, 4):
            obs, _, _, _, infos = env.step(GOOD)
            np.testing.assert_array_equal(infos['episode_steps'], [k, k])


if __name__ == '__main__':
    rospy.init_node('test_python_bad_input', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_python_bad_input', TestBadInput)
