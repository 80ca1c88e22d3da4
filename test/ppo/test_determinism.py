#!/usr/bin/python3
"""Two trainings with the same seed (run side by side by determinism.test) write identical
progress.csv files, timing columns aside."""
import os
import unittest

import rospy
import rostest

from ppo_test_util import StatsWatcher, learning_columns


class TestDeterminism(unittest.TestCase):
    def test_same_seed_same_curve(self):
        iterations = rospy.get_param('~iterations')
        a = StatsWatcher('/a/jetbot_ppo_trainer/training_stats')
        b = StatsWatcher('/b/jetbot_ppo_trainer/training_stats')
        a.wait_iteration(iterations)
        b.wait_iteration(iterations)
        rows_a = learning_columns(os.path.join(rospy.get_param('~run_dir_a'), 'progress.csv'))
        rows_b = learning_columns(os.path.join(rospy.get_param('~run_dir_b'), 'progress.csv'))
        self.assertEqual(len(rows_a), iterations + 1)
        self.assertIn('mean_reward_per_step', rows_a[0])
        self.assertNotIn('elapsed_s', rows_a[0])
        for row_a, row_b in zip(rows_a, rows_b):
            self.assertEqual(row_a, row_b)
        # The curve moves (identical constant rows would prove nothing).
        column = rows_a[0].index('mean_reward_per_step')
        self.assertGreater(len(set(row[column] for row in rows_a[1:])), iterations // 2)


if __name__ == '__main__':
    rospy.init_node('test_determinism')
    rostest.rosrun('jetbot_rl', 'test_determinism', TestDeterminism)
