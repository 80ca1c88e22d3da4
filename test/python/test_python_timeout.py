#!/usr/bin/python3
"""JetbotVecEnv against a node that is killed (SIGKILL) and restarted (2 envs, velocity task)."""
import os
import signal
import subprocess
import time
import unittest

import numpy as np
import rospy
import rostest

from jetbot_rl import EnvRejectedError, JetbotVecEnv
from jetbot_rl.msg import EnvSpec
from jetbot_rl.process_info import node_pid
from jetbot_rl_test.py_test_util import EventList

NODE = '/jetbot_env'
STEP_TIMEOUT = 3.0  # s
GOOD = np.full((2, 2), 5.0, dtype=np.float32)


class TestTimeout(unittest.TestCase):
    def setUp(self):
        self.replacement = None

    def tearDown(self):
        if self.replacement is not None and self.replacement.poll() is None:
            self.replacement.terminate()
            self.replacement.wait(30)

    def kill_node(self):
        os.kill(node_pid(NODE), signal.SIGKILL)

    def restart_node(self):
        """Starts a new jetbot_env (the launch file's parameters are still on the server) and
        waits for its latched spec."""
        specs = EventList()
        sub = rospy.Subscriber(NODE + '/spec', EnvSpec, specs.append)
        self.replacement = subprocess.Popen(['rosrun', 'jetbot_rl', 'jetbot_env_node',
                                             '__name:=jetbot_env'])
        specs.wait_for(lambda: len(specs) > 0, 'the spec of the restarted node')
        sub.unregister()

    def test_killed_and_restarted(self):
        env = JetbotVecEnv(NODE, timeout=STEP_TIMEOUT)
        env.reset()
        for _ in range(3):
            env.step(GOOD)

        # a restarted node is at step 0: it refuses targets for step 3, and says why
        self.kill_node()
        self.restart_node()
        with self.assertRaisesRegex(EnvRejectedError, r'/jetbot_env rejected the request: '
                                    r'future step 3: the current step is 0 .*restarted\?'):
            env.step(GOOD)
        with self.assertRaisesRegex(RuntimeError, r'call reset\(\)'):
            env.step(GOOD)
        env.reset()  # re-synchronised with the new node
        _, _, _, _, infos = env.step(GOOD)
        np.testing.assert_array_equal(infos['episode_steps'], [1, 1])

        # a killed node: TimeoutError naming it, after the timeout
        self.kill_node()
        start = time.monotonic()
        with self.assertRaisesRegex(TimeoutError, r'/jetbot_env did not answer step 1 within '
                                    r'3.0 s \(its ~step service: .*\)'):
            env.step(GOOD)
        self.assertGreaterEqual(time.monotonic() - start, STEP_TIMEOUT)
        self.assertLess(time.monotonic() - start, STEP_TIMEOUT + 5.0)
        with self.assertRaisesRegex(TimeoutError, r'/jetbot_env: ~reset unreachable for 3.0 s'):
            env.reset()
        env.close()
        # no node: the constructor gives up after the timeout, naming it
        with self.assertRaisesRegex(TimeoutError, '/jetbot_env: no latched spec'):
            JetbotVecEnv(NODE, timeout=1.0)


if __name__ == '__main__':
    rospy.init_node('test_python_timeout', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_python_timeout', TestTimeout)
