#!/usr/bin/python3
"""Trainings with the same seed (run side by side by determinism.test: two through env nodes, one
with the env in the trainer's process, one with env and trainer as nodelets of one manager) write
identical progress.csv files, timing columns aside."""
import os
import unittest

import rospy
import rostest

from jetbot_rl_test.ppo_test_util import learning_columns, wait_completed


class TestDeterminism(unittest.TestCase):
    def test_same_seed_same_curve(self):
        iterations = rospy.get_param('~iterations')
        # The trainings started with the launch, perhaps before this node: their run directories
        # (a latched ~training_stats ends with its trainer, which may be before we connect).
        run_dirs = {name: rospy.get_param('~run_dir_' + name) for name in 'abcd'}
        for run_dir in run_dirs.values():
            wait_completed(run_dir)
        rows = {name: learning_columns(os.path.join(run_dirs[name], 'progress.csv'))
                for name in 'abcd'}
        rows_a = rows['a']
        self.assertEqual(len(rows_a), iterations + 1)
        self.assertIn('mean_reward_per_step', rows_a[0])
        self.assertNotIn('elapsed_s', rows_a[0])
        for name in 'bcd':
            self.assertEqual(len(rows[name]), len(rows_a), name)
            for row_a, row in zip(rows_a, rows[name]):
                self.assertEqual(row_a, row, 'run %s differs from run a' % name)
        # The curve moves (identical constant rows would prove nothing).
        column = rows_a[0].index('mean_reward_per_step')
        self.assertGreater(len(set(row[column] for row in rows_a[1:])), iterations // 2)


if __name__ == '__main__':
    rospy.init_node('test_determinism')
    rostest.rosrun('jetbot_rl', 'test_determinism', TestDeterminism)
