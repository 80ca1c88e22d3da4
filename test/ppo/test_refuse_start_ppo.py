#!/usr/bin/python3
"""jetbot_ppo_trainer and jetbot_policy_node refuse bad parameters at start-up: non-zero exit and
a FATAL line naming the parameter and its value."""
import unittest

import rospy
import rostest

from ppo_test_util import run_node

RUN_TIMEOUT = 60.0


class TestRefuseStartPpo(unittest.TestCase):
    count = 0

    def refuses(self, node_type, params, *texts):
        TestRefuseStartPpo.count += 1
        code, output = run_node(node_type, 'refuse_%d' % TestRefuseStartPpo.count, params,
                                timeout=RUN_TIMEOUT)
        self.assertNotEqual(code, 0, output)
        fatal = [line for line in output.splitlines() if 'FATAL' in line]
        self.assertTrue(fatal, 'no FATAL line in:\n' + output)
        for text in texts:
            self.assertIn(text, fatal[0], output)

    def test_learning_rate_negative(self):
        self.refuses('jetbot_ppo_trainer', {'learning_rate': -0.001}, 'learning_rate = -0.001')

    def test_gamma_above_one(self):
        self.refuses('jetbot_ppo_trainer', {'gamma': 1.5}, 'gamma = 1.5')

    def test_activation_unknown(self):
        self.refuses('jetbot_ppo_trainer', {'activation': 'sigmoid'}, 'activation', 'sigmoid')

    def test_hidden_dims_wrong_type(self):
        self.refuses('jetbot_ppo_trainer', {'actor_hidden_dims': 'wide'}, 'actor_hidden_dims')

    def test_env_node_name_invalid(self):
        self.refuses('jetbot_ppo_trainer', {'envs': '[a, b]'}, 'envs', '[a, b]',
                     'not a valid ROS name')

    def test_iterations_zero(self):
        self.refuses('jetbot_ppo_trainer', {'iterations': 0}, 'iterations = 0')

    def test_num_mini_batches_zero(self):
        self.refuses('jetbot_ppo_trainer', {'num_mini_batches': 0}, 'num_mini_batches = 0')

    def test_obs_stats_from_step_below_minus_one(self):
        self.refuses('jetbot_ppo_trainer', {'obs_stats_from_step': -2},
                     'obs_stats_from_step = -2')

    def test_resume_missing(self):
        self.refuses('jetbot_ppo_trainer', {'resume': '/nonexistent/latest.pt'}, 'resume',
                     '/nonexistent/latest.pt')

    def test_player_without_checkpoint(self):
        self.refuses('jetbot_policy_node', {}, 'checkpoint')

    def test_player_missing_checkpoint(self):
        self.refuses('jetbot_policy_node', {'checkpoint': '/nonexistent/best.pt'},
                     '/nonexistent/best.pt')

    def test_player_bad_mode(self):
        self.refuses('jetbot_policy_node', {'checkpoint': '/x.pt', 'mode': 'fast'}, 'mode',
                     'fast')


if __name__ == '__main__':
    rospy.init_node('test_refuse_start_ppo')
    rostest.rosrun('jetbot_rl', 'test_refuse_start_ppo', TestRefuseStartPpo)
