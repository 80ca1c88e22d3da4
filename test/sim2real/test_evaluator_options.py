#!/usr/bin/python3
"""jetbot_rl_evaluate refuses bad command lines: exit code 2 naming the option and value; a
checkpoint that cannot be read ends with 1, naming it. (No node: the program runs in-process.)"""
import os
import subprocess
import tempfile
import unittest

import rostest

from jetbot_rl_test.env_client import TIMEOUT


class TestEvaluatorOptions(unittest.TestCase):
    def evaluate(self, *args):
        """Runs jetbot_rl_evaluate with `args`; returns (exit code, stdout, stderr)."""
        done = subprocess.run(['rosrun', 'jetbot_rl', 'jetbot_rl_evaluate'] + list(args),
                              capture_output=True, text=True, timeout=10 * TIMEOUT)
        return done.returncode, done.stdout, done.stderr

    def test_evaluator_refuses_bad_options(self):
        """Every bad command line ends with exit code 2 and names the option and value; a
        checkpoint that cannot be read ends with 1, naming it."""
        cases = [(['--checkpoint', '/x', '--num-envs', '0'], 'invalid --num-envs = 0'),
                 (['--checkpoint', '/x', '--num-envs', '4x'], 'invalid --num-envs = 4x'),
                 (['--checkpoint', '/x', '--envs', '4'], '--envs was renamed --num-envs'),
                 (['--checkpoint', '/x', '--steps', '-1'], 'invalid --steps = -1'),
                 (['--checkpoint', '/x', '--seed', '99999999999999999999'], 'invalid --seed'),
                 (['--checkpoint', '/x', '--steps'], '--steps needs a value'),
                 (['--checkpoint', '/x', '--speed', '1'], 'unknown option --speed'),
                 (['--num-envs', '4'], '--checkpoint is required')]
        for args, message in cases:
            code, _, err = self.evaluate(*args)
            self.assertEqual(code, 2, args)
            self.assertIn(message, err, args)
        missing = os.path.join(tempfile.mkdtemp(), 'none.pt')
        code, _, err = self.evaluate('--checkpoint', missing, '--steps', '1')
        self.assertEqual(code, 1)
        self.assertIn(missing, err)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_evaluator_options', TestEvaluatorOptions)
