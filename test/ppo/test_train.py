#!/usr/bin/python3
"""A short training through train.launch: progress.csv and ~training_stats, the mean reward per
step rises from the random-policy level, the run directory holds config and checkpoints; then
the trained policy, played in lockstep mode, drives straight with both wheels at the limit."""
import os
import threading
import unittest

import rospy
import rostest
from std_msgs.msg import Float32

from jetbot_rl.msg import WheelTargets
from jetbot_rl_test.ppo_test_util import REQUIRED_HEADER, TIMEOUT, StatsWatcher, read_csv, run_node

RANDOM_LEVEL = 0.25   # m/s: the first iteration (std 1 noise) is about 0.13
MAX_REWARD = 0.6      # m/s: 20 rad/s x 0.03 m
WHEEL_LIMIT = 20.0    # rad/s


class TestTrain(unittest.TestCase):
    def test_train_then_play(self):
        run_dir = rospy.get_param('~run_dir')
        iterations = rospy.get_param('~iterations')
        stats = StatsWatcher('/jetbot_ppo_trainer/training_stats')
        last = stats.wait_iteration(iterations)

        header, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertTrue(header.startswith(REQUIRED_HEADER), header)
        self.assertEqual([int(r['iteration']) for r in rows], list(range(1, iterations + 1)))
        self.assertEqual(int(rows[-1]['env_steps']), int(last['env_steps']))
        self.assertAlmostEqual(rows[-1]['mean_reward_per_step'], last['mean_reward_per_step'],
                               places=5)
        first = rows[0]['mean_reward_per_step']
        tail = rows[-5:]
        final = sum(r['mean_reward_per_step'] for r in tail) / len(tail)
        self.assertLess(first, RANDOM_LEVEL, 'the first iteration is not random-policy-like')
        self.assertGreater(final, 0.85 * MAX_REWARD,
                           'mean reward per step of the last 5 iterations: %.3f' % final)
        self.assertGreater(final, 3 * first)
        for name in ('config.yaml', 'summary.yaml', 'checkpoints/latest.pt',
                     'checkpoints/best.pt'):
            self.assertTrue(os.path.isfile(os.path.join(run_dir, name)), name)
        with open(os.path.join(run_dir, 'config.yaml')) as f:
            config = f.read()
        self.assertIn('learning_rate:', config)
        self.assertIn('env_num_envs: 100', config)

        # --- play the trained policy in lockstep mode on the same env ---
        targets = []
        returns = []
        lock = threading.Lock()

        def on_targets(msg):
            with lock:
                targets.append(msg.velocities)

        def on_return(msg):
            with lock:
                returns.append(msg.data)
        rospy.Subscriber('/jetbot_env/wheel_targets', WheelTargets, on_targets)
        rospy.Subscriber('/jetbot_policy/episode_return', Float32, on_return)
        code, output = run_node('jetbot_policy_node', 'jetbot_policy', {
            'checkpoint': os.path.join(run_dir, 'checkpoints/latest.pt'),
            'mode': 'lockstep', 'steps': 1200, 'reset_seed': 0}, timeout=TIMEOUT)
        self.assertEqual(code, 0, output)
        self.assertIn('drove 1200 steps', output)
        with lock:
            received, episode_returns = list(targets), list(returns)
        self.assertGreater(len(received), 600, 'wheel targets seen: %d' % len(received))
        straight = 0
        total = 0
        for velocities in received[10:]:
            for e in range(0, len(velocities), 2):
                left, right = velocities[e], velocities[e + 1]
                total += 1
                if (abs(left) >= 0.98 * WHEEL_LIMIT and abs(right) >= 0.98 * WHEEL_LIMIT
                        and left * right > 0):
                    straight += 1
        self.assertGreater(straight, 0.98 * total,
                           '%d of %d env steps with both wheels at the limit, same sign'
                           % (straight, total))
        self.assertTrue(episode_returns, 'no ~episode_return received')
        mean_return = sum(episode_returns) / len(episode_returns)
        self.assertGreater(mean_return, 0.9 * MAX_REWARD * 299, output)


if __name__ == '__main__':
    rospy.init_node('test_train')
    rostest.rosrun('jetbot_rl', 'test_train', TestTrain)
