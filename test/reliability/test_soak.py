#!/usr/bin/python3
"""Soak: bench/soak.py against the node of soak.test: lockstep steps of 100 envs with a ~reset
of one env after every step; step ids consecutive throughout, the node's resident set flat within
2 MB after the warm-up. Prints soak.py's figures."""
import subprocess
import unittest

import rospy
import rostest

from jetbot_rl_test.fault_util import PYTHON, package_file

SOAK = package_file('bench', 'soak.py')


class TestSoak(unittest.TestCase):
    def test_soak(self):
        steps = rospy.get_param('~steps')
        proc = subprocess.run(
            [PYTHON, SOAK, '--steps', str(steps), '--warmup', str(steps // 10),
             '--max-rss-growth-kb', '2048'],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
            timeout=rospy.get_param('~timeout'))
        print(proc.stdout)
        self.assertEqual(proc.returncode, 0, proc.stdout)
        self.assertIn('FIGURE: soak:', proc.stdout)


if __name__ == '__main__':
    rospy.init_node('test_soak')
    rostest.rosrun('jetbot_rl', 'test_soak', TestSoak)
