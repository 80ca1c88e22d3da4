#!/usr/bin/python3
"""A short navigation training through train.launch (env node and trainer over topics): the
success rate in progress.csv rises from a random policy's to well above a floor, the outcome
columns add up to one, and the trained policy, evaluated on 200 episodes of unseen seeds with
jetbot_rl_evaluate, reaches the goal in most of them and collides in few."""
import math
import os
import subprocess
import unittest
import zipfile

import rospkg
import rospy
import rostest

from jetbot_rl_test.env_client import wait_for
from jetbot_rl_test.ppo_test_util import TIMEOUT, StatsWatcher, read_csv

SUCCESS_FLOOR = 0.8     # the last 10 iterations' mean success rate
EVAL_SUCCESS_FLOOR = 0.85
EVAL_COLLISION_CEILING = 0.1
PKG = rospkg.RosPack().get_path('jetbot_rl')


def exported_meta(run_dir):
    """The export's meta.yaml as a dict of strings; {} while it is not (completely) written."""
    try:
        with zipfile.ZipFile(os.path.join(run_dir, 'exported', 'policy.pt')) as z:
            name = next(n for n in z.namelist() if n.endswith('extra/meta.yaml'))
            text = z.read(name).decode()
    except (OSError, zipfile.BadZipFile, StopIteration):
        return {}
    return dict(line.split(': ', 1) for line in text.splitlines()
                if ': ' in line and not line.startswith('#'))


class TestTrainNavigation(unittest.TestCase):
    def test_train_then_evaluate(self):
        run_dir = rospy.get_param('~run_dir')
        iterations = rospy.get_param('~iterations')
        StatsWatcher('/jetbot_ppo_trainer/training_stats').wait_iteration(iterations, timeout=240.0)
        header, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        for column in ('success_rate', 'collision_rate', 'timeout_rate'):
            self.assertIn(column, header.split(','))
        for r in rows:
            if not math.isnan(r['success_rate']):
                self.assertAlmostEqual(r['success_rate'] + r['collision_rate'] + r['timeout_rate'],
                                       1.0, places=5)
        first = [r['success_rate'] for r in rows[:3] if not math.isnan(r['success_rate'])]
        last = [r['success_rate'] for r in rows[-10:] if not math.isnan(r['success_rate'])]
        success = sum(last) / len(last)
        print('FIGURE: navigation training: success rate %.2f in the first iterations, %.2f in the '
              'last 10 of %d' % (sum(first) / max(len(first), 1), success, iterations))
        self.assertGreater(success, SUCCESS_FLOOR)

        out = subprocess.run(
            ['rosrun', 'jetbot_rl', 'jetbot_rl_evaluate', '--checkpoint', run_dir, '--urdf',
             os.path.join(PKG, 'urdf', 'jetbot_lidar.urdf'), '--config',
             os.path.join(PKG, 'config', 'jetbot_env.yaml'), '--config',
             os.path.join(PKG, 'config', 'navigation_env.yaml'), '--config',
             os.path.join(PKG, 'config', 'world_generated.yaml'), '--task', 'navigation',
             '--num-envs', '50', '--episodes', '200', '--steps', '100000', '--seed', '5000'],
            check=True, stdout=subprocess.PIPE, universal_newlines=True, timeout=TIMEOUT * 6).stdout
        figures = dict(line.split('=', 1) for line in out.splitlines() if '=' in line)
        print('FIGURE: navigation evaluation (200 episodes, seed 5000): ' + out.replace('\n', ' '))
        self.assertEqual(figures['episodes'].split()[0], '200')
        self.assertGreater(float(figures['success_rate']), EVAL_SUCCESS_FLOOR)
        self.assertLess(float(figures['collision_rate']), EVAL_COLLISION_CEILING)

        # The beams it observed travelled from the env node (~spec) into the export's meta.yaml:
        # config/navigation_env.yaml's 24 beams, each 15 of its 360 samples over
        # [-3.14159, 3.12414] rad, 0.15-3.5 m, on a log scale.
        wait_for(lambda: exported_meta(run_dir), timeout=TIMEOUT, what='the exported policy',
                 recheck=0.5)
        meta = exported_meta(run_dir)
        angles = [float(a) for a in meta['scan_beam_angles'].strip('[]').split(',')]
        self.assertEqual(len(angles), 24)
        for k, angle in enumerate(angles):
            self.assertAlmostEqual(angle, -3.14159 + 15 * k * (3.12414 + 3.14159) / 359, places=9)
        self.assertEqual(meta['scan_range'], '[0.15, 3.5]')
        self.assertTrue(meta['observation_names'].startswith('[beam_log_0, '), meta)


if __name__ == '__main__':
    rospy.init_node('test_train_navigation')
    rostest.rosrun('jetbot_rl', 'test_train_navigation', TestTrainNavigation)
