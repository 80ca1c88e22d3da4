#!/usr/bin/python3
"""SIGINT (Ctrl-C) makes the trainer save checkpoints/latest.pt and exit cleanly; resuming from
the run directory continues the iteration count, env steps and progress.csv."""
import os
import signal
import tempfile
import unittest

import rospy
import rostest

from jetbot_rl_test.ppo_test_util import TIMEOUT, StatsWatcher, read_csv, run_node, start_node

STEPS_PER_ITERATION = 16 * 16  # num_steps_per_env x num_envs


class TestInterruptResume(unittest.TestCase):
    def test_sigint_then_resume(self):
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_interrupt_')  # never shared by two runs
        stats = StatsWatcher('/trainer_a/training_stats')
        proc = start_node('jetbot_ppo_trainer', 'trainer_a', {
            'env_nodes': '/jetbot_env', 'iterations': 1000000, 'run_dir': run_dir,
            'save_interval': 1000})
        try:
            stats.wait_iteration(3)
        finally:
            proc.send_signal(signal.SIGINT)
            output, _ = proc.communicate(timeout=TIMEOUT)
        self.assertEqual(proc.returncode, 0, output)
        self.assertIn('interrupted', output)
        self.assertIn('status: interrupted', output)
        self.assertTrue(os.path.isfile(os.path.join(run_dir, 'checkpoints/latest.pt')))
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        done = len(rows)
        self.assertGreaterEqual(done, 3)
        with open(os.path.join(run_dir, 'summary.yaml')) as f:
            self.assertIn('iterations: %d\n' % done, f.read())

        # Resume from the run directory (its checkpoints/latest.pt) for two more iterations.
        code, output = run_node('jetbot_ppo_trainer', 'trainer_b', {
            'env_nodes': '/jetbot_env', 'iterations': done + 2, 'resume': run_dir})
        self.assertEqual(code, 0, output)
        self.assertIn('resumed from', output)
        self.assertIn('at iteration %d' % done, output)
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertEqual([int(r['iteration']) for r in rows], list(range(1, done + 3)))
        self.assertEqual([int(r['env_steps']) for r in rows],
                         [STEPS_PER_ITERATION * i for i in range(1, done + 3)])
        self.assertGreater(rows[-1]['elapsed_s'], rows[done - 1]['elapsed_s'])
        with open(os.path.join(run_dir, 'summary.yaml')) as f:
            summary = f.read()
        self.assertIn('status: completed', summary)
        self.assertIn('iterations: %d\n' % (done + 2), summary)


if __name__ == '__main__':
    rospy.init_node('test_interrupt_resume')
    rostest.rosrun('jetbot_rl', 'test_interrupt_resume', TestInterruptResume)
