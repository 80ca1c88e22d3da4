#!/usr/bin/python3
"""scripts/ppo_example.py trains briefly through JetbotVecEnv (100 envs, 12 iterations, seed 0),
clearly beating the random policy of its first iteration, then plays the saved policy, also with
an observation and action history (25 iterations, above 0.25 per step). Its renamed options (and those of bench/python_bench.py, the other program
on JetbotVecEnv) are refused naming the new ones. Against a navigation node it reports the
navigation task's target, a success rate, instead of the velocity task's reward per step. With
--signals (python_ppo_example_signals.test): Ctrl-C and SIGTERM mid-training save the policy and
exit 0 within 2 s."""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rostest

ITERATIONS = 12  # seed 0 here: 0.45 per step from iteration 8, 0.53 at 12 (0.57 at 20)
# The history policy's input is 4 times wider: it learns more slowly (0.30 at 20 iterations, seed
# 0, here; it settles near 0.57 after 60; after 12 its play got only 0.30). The test asks for
# learning, not a trained policy: 25 iterations, above RANDOM_LEVEL (the random policy gets about
# 0.13 per step).
HISTORY_ITERATIONS = 25
HISTORY_LEVEL = 0.25
RANDOM_LEVEL = 0.25  # m/s: the random policy gets about 0.13 per step


def run(*args):
    out = subprocess.run(['rosrun', 'jetbot_rl', 'ppo_example.py'] + list(args),
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=180)
    print(out.stdout)
    assert out.returncode == 0, 'ppo_example.py %s failed:\n%s' % (' '.join(args), out.stdout)
    return out.stdout


def value(text, key):
    match = re.search(r'%s=([-0-9.e+]+|never)' % key, text)
    assert match, '%s missing in:\n%s' % (key, text)
    return match.group(1)


class TestPpoExample(unittest.TestCase):
    def test_trains_saves_and_plays(self):
        with tempfile.TemporaryDirectory() as tmp:
            policy = os.path.join(tmp, 'policy.pt')
            out = run('--iterations', str(ITERATIONS), '--seed', '0', '--save', policy)
            rewards = [float(r) for r in re.findall(r'reward/step ([0-9.]+)', out)]
            self.assertEqual(len(rewards), ITERATIONS)
            self.assertLess(rewards[0], RANDOM_LEVEL, 'the first iteration is not random-like')
            self.assertGreater(min(rewards[-3:]), 0.45, 'no clear improvement: %s' % rewards)
            self.assertGreater(float(value(out, 'final_mean_reward_per_step')), 0.45)
            self.assertTrue(os.path.isfile(policy))
            # the velocity task's target: 0.54 m/s per step
            self.assertIn('target=reward/step >= 0.54\n', out)
            self.assertRegex(out, r'\nreward/step >= 0\.54 (reached at iteration \d+ \(\d+ env '
                                  r'steps, [0-9.]+ s\)|not reached in %d iterations)\n' % ITERATIONS)

            out = run('--play', policy, '--play-steps', '300')
            self.assertGreater(float(value(out, 'play_mean_reward_per_step')), 0.45)
            self.assertGreater(float(value(out, 'play_mean_episode_return')), 0.45 * 299)

    def test_trains_and_plays_with_a_history(self):
        """--obs-history 3 --action-history 2: the policy sees 3 x 3 + 2 x 2 inputs, learns (over
        HISTORY_ITERATIONS), and plays from its saved history lengths; a bad length is refused
        naming it."""
        with tempfile.TemporaryDirectory() as tmp:
            policy = os.path.join(tmp, 'policy.pt')
            out = run('--iterations', str(HISTORY_ITERATIONS), '--seed', '0', '--save', policy,
                      '--obs-history', '3', '--action-history', '2')
            self.assertGreater(float(value(out, 'final_mean_reward_per_step')), HISTORY_LEVEL)
            script = ('import torch; s = torch.load(%r); '
                      'print(s["obs_history"], s["action_history"], '
                      's["model"]["actor.0.weight"].shape[1])' % policy)
            saved = subprocess.run(['/usr/bin/python3', '-c', script], stdout=subprocess.PIPE,
                                   text=True, check=True).stdout.split()
            self.assertEqual(saved, ['3', '2', str(3 * 3 + 2 * 2)])
            out = run('--play', policy, '--play-steps', '300')
            self.assertGreater(float(value(out, 'play_mean_reward_per_step')), HISTORY_LEVEL)
        for option in ('--obs-history', '--action-history'):
            out = subprocess.run(['rosrun', 'jetbot_rl', 'ppo_example.py', option, '-1'],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=60)
            self.assertEqual(out.returncode, 2, out.stdout)
            self.assertIn('invalid %s = -1' % option, out.stdout)

    def test_navigation_reports_the_success_rate(self):
        """Against the navigation node: the target is a success rate (0.9 by default), reported
        as reached at an iteration or not reached, never the velocity task's reward per step;
        --target 0 is reached at the first iteration in which some episode ended."""
        with tempfile.TemporaryDirectory() as tmp:
            policy = os.path.join(tmp, 'policy.pt')
            out = run('--env-nodes', '/nav/jetbot_env', '--iterations', '2', '--num-steps', '32',
                      '--save', policy)
            self.assertIn('target=success rate >= 0.90 (episodes ended in an iteration)\n', out)
            self.assertRegex(out, r'\nsuccess rate >= 0\.90 (reached at iteration [12] |not '
                                  r'reached in 2 iterations\n)')
            self.assertNotIn('reward/step >=', out)  # not the velocity task's target
            value(out, 'target_reached_at_iteration')
            out = run('--env-nodes', '/nav/jetbot_env', '--iterations', '4', '--num-steps', '100',
                      '--target', '0', '--save', policy)
            ended = [i + 1 for i, line in enumerate(re.findall(r'^iteration \d+/4 .*$', out, re.M))
                     if ' | success ' in line]
            self.assertTrue(ended, 'no episode ended in 4 iterations:\n' + out)
            self.assertIn('\nsuccess rate >= 0.00 reached at iteration %d (' % ended[0], out)
            self.assertEqual(value(out, 'target_reached_at_iteration'), str(ended[0]))

    def test_renamed_options_are_refused(self):
        """An old option name ends the program with exit code 2 before it looks for a node, and
        the error names the new option; the new names are accepted."""
        cases = [('ppo_example.py', ['--node', '/jetbot_env'], '--node was renamed --env-nodes'),
                 ('ppo_example.py', ['--env-nodes', '/jetbot_env', '--node', '/jetbot_env'],
                  '--node was renamed --env-nodes'),
                 ('python_bench.py', ['--envs', '100', '--steps', '10'],
                  '--envs was renamed --num-envs'),
                 ('python_bench.py',
                  ['--num-envs', '100', '--steps', '10', '--node', '/jetbot_env'],
                  '--node was renamed --env-nodes')]
        for program, args, message in cases:
            out = subprocess.run(['rosrun', 'jetbot_rl', program] + args, stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True, timeout=60)
            self.assertEqual(out.returncode, 2, '%s %s:\n%s' % (program, args, out.stdout))
            self.assertIn('error: ' + message, out.stdout, program)
        for program in ('ppo_example.py', 'python_bench.py'):
            out = subprocess.run(['rosrun', 'jetbot_rl', program, '--help'],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=60)
            self.assertEqual(out.returncode, 0, out.stdout)
            self.assertIn('--env-nodes', out.stdout)
            self.assertNotIn('--node ', out.stdout)
        # the new names work: python_bench.py steps the node of this test (100 envs)
        out = subprocess.run(['rosrun', 'jetbot_rl', 'python_bench.py', '--num-envs', '100',
                              '--steps', '20', '--env-nodes', '/jetbot_env'],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=120)
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertIn('env_steps_per_s=', out.stdout)


class TestPpoExampleSignals(unittest.TestCase):
    """Timed (the exit within 2 s of a signal): python_ppo_example_signals.test, in the
    foreground lane of the test run (the trainings above run beside it, niced)."""

    def test_ctrl_c_saves_the_policy(self):
        """SIGINT (Ctrl-C) and SIGTERM mid-training: the last whole iteration's policy is saved,
        exit 0."""
        for sig in (signal.SIGINT, signal.SIGTERM):
            with tempfile.TemporaryDirectory() as tmp:
                policy = os.path.join(tmp, 'policy.pt')
                proc = subprocess.Popen(
                    ['rosrun', 'jetbot_rl', 'ppo_example.py', '--iterations', '100000',
                     '--save', policy], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                    text=True)
                lines = []
                for line in proc.stdout:  # until the first iteration is done
                    lines.append(line)
                    if line.startswith('iteration 1/'):
                        break
                signalled = time.monotonic()
                proc.send_signal(sig)
                rest, _ = proc.communicate(timeout=30)
                exit_s = time.monotonic() - signalled
                out = ''.join(lines) + rest
                print(out)
                print('FIGURE: ppo_example.py: exit status %d %.2f s after %s'
                      % (proc.returncode, exit_s, sig.name))
                self.assertEqual(proc.returncode, 0, out)
                self.assertLess(exit_s, 2.0)
                self.assertIn('status=interrupted', out)
                self.assertTrue(os.path.isfile(policy))
                out = run('--play', policy, '--play-steps', '20')
                self.assertIn('play_mean_reward_per_step=', out)


if __name__ == '__main__':
    rospy.init_node('test_python_ppo_example', disable_signals=True)
    if '--signals' in sys.argv:
        rostest.rosrun('jetbot_rl', 'test_python_ppo_example_signals', TestPpoExampleSignals)
    else:
        rostest.rosrun('jetbot_rl', 'test_python_ppo_example', TestPpoExample)
