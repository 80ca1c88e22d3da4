#!/usr/bin/python3
"""The trainer over two env nodes as one batch: it learns; a node whose spec differs is refused
with its name and the field; a node killed mid-training ends the run within step_timeout with a
checkpoint and an error naming the node; resuming with the same list continues the CSV."""
import os
import signal
import subprocess
import tempfile
import time
import unittest

import rospy
import rostest
from jetbot_rl.process_info import node_pid
from jetbot_rl_test.ppo_test_util import TIMEOUT, StatsWatcher, read_csv, run_node, start_node

NODES = ['/jetbot_env_0', '/jetbot_env_1']
STEP_TIMEOUT = 3.0
STEPS_PER_ITERATION = 16 * 64
LEARNED_AT = 30  # iterations


class TestTwoNodes(unittest.TestCase):
    def test_mismatched_node_is_refused_by_name_and_field(self):
        rospy.set_param('/trainer_odd/env_nodes', ['/jetbot_env_0', '/jetbot_env_odd'])
        code, output = run_node('jetbot_ppo_trainer', 'trainer_odd', {
            'iterations': 1, 'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_odd_')})
        self.assertNotEqual(code, 0, output)
        fatal = [line for line in output.splitlines() if 'FATAL' in line]
        self.assertTrue(fatal, output)
        self.assertIn('/jetbot_env_odd', fatal[0])
        self.assertIn('observation_names', fatal[0])

    def test_learns_then_a_killed_node_ends_the_run_and_resume_continues(self):
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_two_nodes_')
        stats = StatsWatcher('/trainer_two/training_stats')
        rospy.set_param('/trainer_two/env_nodes', NODES)  # a list: command-line params are scalars
        rospy.set_param('/trainer_resumed/env_nodes', NODES)
        proc = start_node('jetbot_ppo_trainer', 'trainer_two', {
            'iterations': 1000000, 'run_dir': run_dir,
            'step_timeout': STEP_TIMEOUT, 'save_interval': 1000})
        try:
            stats.wait_iteration(LEARNED_AT, timeout=3 * TIMEOUT)
            killed_at = time.monotonic()
            os.kill(node_pid('/jetbot_env_1'), signal.SIGKILL)
            output, _ = proc.communicate(timeout=TIMEOUT)
            stopped_after = time.monotonic() - killed_at
        finally:
            if proc.poll() is None:
                proc.send_signal(signal.SIGINT)
                proc.communicate(timeout=TIMEOUT)
        print('FIGURE: the trainer stopped %.2f s after jetbot_env_1 was killed '
              '(step_timeout %.1f s)' % (stopped_after, STEP_TIMEOUT))
        self.assertNotEqual(proc.returncode, 0, output)
        self.assertLess(stopped_after, STEP_TIMEOUT + 5.0)
        self.assertIn('/jetbot_env_1', [line for line in output.splitlines()
                                        if 'training stopped' in line][0])
        with open(os.path.join(run_dir, 'summary.yaml')) as f:
            summary = f.read()
        self.assertIn('status: failed', summary)
        self.assertIn('/jetbot_env_1', summary)
        self.assertTrue(os.path.isfile(os.path.join(run_dir, 'checkpoints/latest.pt')))
        with open(os.path.join(run_dir, 'config.yaml')) as f:
            self.assertIn('env_num_envs: 64', f.read())
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        done = len(rows)
        self.assertGreaterEqual(done, LEARNED_AT)
        first = rows[0]['mean_reward_per_step']
        last = sum(r['mean_reward_per_step'] for r in rows[-5:]) / 5
        print('FIGURE: two nodes, 64 envs: reward per step %.3f at iteration 1, %.3f over '
              'iterations %d-%d' % (first, last, done - 4, done))
        self.assertLess(first, 0.25)
        self.assertGreater(last, first + 0.2)

        # The node comes back (its parameters are still on the master); the same list resumes.
        env = subprocess.Popen(['rosrun', 'jetbot_rl', 'jetbot_env_node', '__name:=jetbot_env_1'],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            code, output = run_node('jetbot_ppo_trainer', 'trainer_resumed', {
                'iterations': done + 2, 'resume': run_dir},
                timeout=2 * TIMEOUT)
        finally:
            env.send_signal(signal.SIGINT)
            env.wait(timeout=TIMEOUT)
        self.assertEqual(code, 0, output)
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertEqual([int(r['iteration']) for r in rows], list(range(1, done + 3)))
        self.assertEqual([int(r['env_steps']) for r in rows],
                         [STEPS_PER_ITERATION * i for i in range(1, done + 3)])


if __name__ == '__main__':
    rospy.init_node('test_two_nodes')
    rostest.rosrun('jetbot_rl', 'test_two_nodes', TestTwoNodes)
