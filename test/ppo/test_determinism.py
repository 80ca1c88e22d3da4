#!/usr/bin/python3
"""Trainings with the same seed (run side by side by determinism.test: two through env nodes, one
with the env in the trainer's process, one with env and trainer as nodelets of one manager) write
identical progress.csv files, timing columns aside; with ~ros_free (determinism_mix.test), so does
jetbot_rl_train_bench, which trains without ROS from the in-process trainer's parameters written
as YAML files."""
import os
import subprocess
import unittest

import yaml

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
        if rospy.get_param('~ros_free', False):
            self.assertEqual(self._train_without_ros(run_dirs['c']), rows_a, 'ROS-free run differs')

    def _train_without_ros(self, run_dir_c):
        """jetbot_rl_train_bench on run c's parameters (its trainer's, each part's, its robot), as
        a user without a master would write them: the learning columns of its progress.csv."""
        ns = rospy.get_param('~trainer_ns')
        trainer = rospy.get_param(ns)
        env_config = trainer.pop('env_config')
        files = os.path.join(run_dir_c + '_ros_free_params')
        os.makedirs(files, exist_ok=True)

        def write(name, content):
            path = os.path.join(files, name)
            with open(path, 'w') as f:
                f.write(content if isinstance(content, str) else yaml.safe_dump(content))
            return path
        args = ['rosrun', 'jetbot_rl', 'jetbot_rl_train_bench',
                '--trainer', write('trainer.yaml', trainer),
                '--urdf', write('robot.urdf', rospy.get_param(rospy.get_param('~robot_description'))),
                '--run-dir', run_dir_c + '_ros_free']
        for part in trainer['env_nodes']:  # one part each, in the batch's order
            args += ['--part', write(part + '.yaml', env_config[part])]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL, timeout=240)
        return learning_columns(os.path.join(run_dir_c + '_ros_free', 'progress.csv'))


if __name__ == '__main__':
    rospy.init_node('test_determinism')
    rostest.rosrun('jetbot_rl', 'test_determinism', TestDeterminism)
