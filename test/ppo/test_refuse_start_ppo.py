#!/usr/bin/python3
"""jetbot_ppo_trainer and jetbot_policy_node refuse bad parameters at start-up: non-zero exit and
a FATAL line naming the parameter and its value."""
import os
import tempfile
import unittest

import rospkg
import rospy
import rostest

from jetbot_rl_test.ppo_test_util import run_node

RUN_TIMEOUT = 60.0
URDF = open(os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'urdf', 'jetbot.urdf')).read()


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
        self.refuses('jetbot_ppo_trainer', {'env_nodes': '[a, b]'}, 'env_nodes', '[a, b]',
                     'not a valid ROS name')

    # --- renamed parameters: the old name is refused with the new one ---
    def test_envs_renamed(self):
        self.refuses('jetbot_ppo_trainer', {'envs': 'jetbot_env'},
                     'invalid envs = (set): was renamed env_nodes')

    def test_player_envs_renamed(self):
        self.refuses('jetbot_policy_node', {'checkpoint': '/x.pt', 'envs': 'jetbot_env'},
                     'invalid envs = (set): was renamed env_nodes')

    def test_in_process_env_reward_renamed(self):
        # ~env_config holds the env node's parameters: the same rename is refused there. With a
        # robot loaded and a small run, only the parameter can stop the trainer, whatever it reads
        # first (and were it not refused, the run would end quickly, in a scratch directory).
        rospy.set_param('/robot_description', URDF)
        self.addCleanup(rospy.delete_param, '/robot_description')
        self.refuses('jetbot_ppo_trainer',
                     {'env_in_process': 'true', 'iterations': 1,
                      'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_refuse_'),
                      'env_config/num_envs': 2, 'env_config/task': 'command',
                      'env_config/reward': 'exp'},
                     'invalid reward = (set): was renamed reward_variant')

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
