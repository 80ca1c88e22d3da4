#!/usr/bin/python3
"""`roslaunch jetbot_rl train.launch` (the README's main job, shortened to 5 iterations) ends by
itself with exit status 0, the summary `status: completed`, and none of roslaunch's banners for
a required node that died."""
import os
import subprocess
import tempfile
import unittest

import rospy
import rostest


class TestCleanEnd(unittest.TestCase):
    def test_main_job_ends_cleanly(self):
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_clean_end_')
        done = subprocess.run(['roslaunch', 'jetbot_rl', 'train.launch', 'iterations:=5',
                               'run_dir:=' + run_dir],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=180)
        tail = done.stdout[-3000:]
        self.assertEqual(done.returncode, 0, tail)
        self.assertNotIn('REQUIRED process', done.stdout, tail)
        self.assertNotIn('has died', done.stdout, tail)
        with open(os.path.join(run_dir, 'summary.yaml')) as f:
            self.assertIn('status: completed', f.read())


if __name__ == '__main__':
    rospy.init_node('test_clean_end', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_clean_end', TestCleanEnd)
