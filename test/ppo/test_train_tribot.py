#!/usr/bin/python3
"""The second robot learns the velocity task: through train.launch with urdf/examples/tribot.urdf
and urdf/examples/tribot.yaml, the mean reward per step rises from the random-policy level to near
its top speed, the wheel velocity limit x the wheel radius (8 rad/s x 0.033 m = 0.264 m/s, read
from the env's ~spec)."""
import os
import unittest

import rospy
import rostest

from jetbot_rl.msg import EnvSpec
from jetbot_rl_test.ppo_test_util import TIMEOUT, StatsWatcher, read_csv


class TestTrainTribot(unittest.TestCase):
    def test_learns_to_drive_at_its_top_speed(self):
        spec = rospy.wait_for_message('/jetbot_env/spec', EnvSpec, TIMEOUT)
        self.assertEqual(list(spec.action_names), ['wheel_left_joint', 'wheel_right_joint'])
        top_speed = spec.action_high[0] * spec.wheel_radius
        self.assertAlmostEqual(top_speed, 8.0 * 0.033, places=6)
        run_dir = rospy.get_param('~run_dir')
        iterations = rospy.get_param('~iterations')
        StatsWatcher('/jetbot_ppo_trainer/training_stats').wait_iteration(iterations)
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertEqual(len(rows), iterations)
        first = rows[0]['mean_reward_per_step']
        tail = rows[-5:]
        final = sum(r['mean_reward_per_step'] for r in tail) / len(tail)
        print('tribot: mean reward per step %.4f m/s at the first iteration, %.4f over the last 5 '
              '(top speed %.3f m/s)' % (first, final, top_speed))
        self.assertLess(first, 0.45 * top_speed, 'the first iteration is not random-policy-like')
        self.assertGreater(final, 0.85 * top_speed,
                           'mean reward per step of the last 5 iterations: %.4f' % final)


if __name__ == '__main__':
    rospy.init_node('test_train_tribot')
    rostest.rosrun('jetbot_rl', 'test_train_tribot', TestTrainTribot)
