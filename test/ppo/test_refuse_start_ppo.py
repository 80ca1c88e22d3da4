#!/usr/bin/python3
"""jetbot_ppo_trainer, jetbot_policy_node, jetbot_deploy_node and jetbot_depth_scan refuse bad
parameters at start-up: non-zero exit and a FATAL line naming the parameter and its value.

Each refused start loads libtorch (about a second): the class first runs every test's starts
three at a time (each test once, collecting what it would start), then each test checks its own
runs' exit codes and output."""
import concurrent.futures
import os
import tempfile
import unittest

import rospkg
import rospy
import rostest

from jetbot_rl_test.ppo_test_util import run_node

RUN_TIMEOUT = 60.0
URDF = open(os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'urdf', 'jetbot.urdf')).read()


PARALLEL_STARTS = 3


class TestRefuseStartPpo(unittest.TestCase):
    collecting = False
    starts = {}   # (test, k): (node type, node name, params, lists), filled while collecting
    results = {}  # (test, k): (exit code, output)

    @classmethod
    def setUpClass(cls):
        # The in-process env of some runs reads the robot from here.
        rospy.set_param('/robot_description', URDF)
        cls.collecting = True
        for name in sorted(n for n in dir(cls) if n.startswith('test_')):
            getattr(cls(name), name)()
        cls.collecting = False
        with concurrent.futures.ThreadPoolExecutor(PARALLEL_STARTS) as pool:
            futures = {key: pool.submit(cls.start, *spec) for key, spec in cls.starts.items()}
            cls.results = {key: f.result() for key, f in futures.items()}

    @classmethod
    def tearDownClass(cls):
        rospy.delete_param('/robot_description')

    @staticmethod
    def start(node_type, name, params, lists):
        for key, value in lists.items():
            rospy.set_param('/%s/%s' % (name, key), value)
        try:
            return run_node(node_type, name, params, timeout=RUN_TIMEOUT)
        finally:
            for key in lists:
                rospy.delete_param('/%s/%s' % (name, key))

    def setUp(self):
        self.calls = 0

    @staticmethod
    def shipped(name):
        """A shipped policy's directory (policies/, what the quick starts play)."""
        return os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies', name)

    def checkpoint(self):
        """A velocity-task policy."""
        return self.shipped('velocity')

    def navigation_checkpoint(self):
        """A navigation policy without a path (config/navigation_arena.yaml): its checkpoint
        holds the beams it observed."""
        return self.shipped('navigation_arena')

    def path_checkpoint(self):
        """A navigation policy that follows a global path (nav/path: the task's defaults)."""
        return self.shipped('navigation')

    def refuses(self, node_type, params, *texts, lists=None):
        """`lists`: private parameters set on the server (a command line gives only scalars)."""
        self.calls = getattr(self, 'calls', 0) + 1
        key = (self._testMethodName, self.calls)
        if TestRefuseStartPpo.collecting:
            name = 'refuse_%s_%d' % key
            TestRefuseStartPpo.starts[key] = (node_type, name, params, lists or {})
            return
        code, output = TestRefuseStartPpo.results[key]
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
        self.refuses('jetbot_ppo_trainer',
                     {'env_in_process': 'true', 'iterations': 1,
                      'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_refuse_'),
                      'env_config/num_envs': 2, 'env_config/task': 'command',
                      'env_config/reward': 'exp'},
                     'invalid reward = (set): was renamed reward_variant')

    def test_in_process_parts_that_disagree(self):
        # Two in-process parts (~env_config/NAME) of different episode lengths cannot be one
        # batch: refused naming both parts and the field, as env nodes that disagree are.
        self.refuses('jetbot_ppo_trainer',
                     {'env_in_process': 'true', 'iterations': 1,
                      'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_refuse_'),
                      'env_config/part_a/num_envs': 2, 'env_config/part_b/num_envs': 3,
                      'env_config/part_b/episode_length_s': 7.0},
                     'env part_b differs from env part_a', 'max_episode_length',
                     lists={'env_nodes': ['part_a', 'part_b']})

    def test_in_process_part_with_a_bad_value(self):
        # A part's own parameters are validated as an env node's, naming the part's namespace.
        self.refuses('jetbot_ppo_trainer',
                     {'env_in_process': 'true', 'iterations': 1,
                      'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_refuse_'),
                      'env_config/part_a/num_envs': 2, 'env_config/part_b/num_envs': -4},
                     'env_config/part_b: invalid num_envs = -4',
                     lists={'env_nodes': ['part_a', 'part_b']})

    # --- memory ---
    def test_obs_history_length_zero(self):
        self.refuses('jetbot_ppo_trainer', {'obs_history_length': 0}, 'obs_history_length = 0')

    def test_rnn_type_unknown(self):
        self.refuses('jetbot_ppo_trainer', {'rnn_type': 'transformer'}, 'rnn_type',
                     'transformer')

    def test_recurrent_minibatches_beyond_the_envs(self):
        # A recurrent minibatch holds whole env sequences: no more of them than envs.
        self.refuses('jetbot_ppo_trainer',
                     {'env_in_process': 'true', 'iterations': 1, 'rnn_type': 'gru',
                      'num_mini_batches': 4,
                      'run_dir': tempfile.mkdtemp(prefix='jetbot_rl_test_refuse_'),
                      'env_config/num_envs': 2},
                     'num_mini_batches = 4', 'num_envs = 2')

    # --- the deploy node takes the control rate, bounds, task and beams from the checkpoint ---
    def test_deploy_control_rate_from_the_checkpoint(self):
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.checkpoint(), 'control_rate': 60.0},
                     'control_rate = (set): comes from the checkpoint now')

    def test_deploy_task_not_the_checkpoints(self):
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.checkpoint(), 'task': 'command'},
                     "task = 'command'", "trained on task 'velocity'")

    def test_deploy_scan_parameters_come_from_the_checkpoint(self):
        # The beams a policy observes are its checkpoint's (its observation contract): the
        # parameters that once gave them are refused by name.
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.navigation_checkpoint()},
                     'scan_range = (set): comes from the checkpoint now (its scan_range)',
                     lists={'scan_range': [0.12, 12.0]})
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.navigation_checkpoint(), 'scan_beams': 24},
                     'scan_beams = (set): comes from the checkpoint now')

    def test_deploy_former_names(self):
        # A simulation parameter of the robot mode's time is refused by its name now.
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.navigation_checkpoint(), 'nav/goal_radius': 0.3},
                     'nav/goal_radius = (set): was renamed xy_goal_tolerance')
        # move_base's name for the goal test.
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.navigation_checkpoint(), 'goal_radius': 0.3},
                     'goal_radius = (set): was renamed xy_goal_tolerance')

    def test_deploy_path_policy_without_a_map(self):
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.path_checkpoint(), 'footprint_radius': 0.1},
                     "map_topic = ''", 'follows a global path, which is planned on a map')

    def test_deploy_local_planner(self):
        # The DWA drives towards goals on a scan: a velocity policy's task has neither.
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.checkpoint(), 'local_planner': 'dwa'},
                     'local_planner = dwa', "task 'velocity' has no goals")
        self.refuses('jetbot_deploy_node',
                     {'checkpoint': self.navigation_checkpoint(), 'local_planner': 'teb'},
                     "local_planner = 'teb'", 'policy', 'dwa')

    def test_deploy_without_checkpoint(self):
        self.refuses('jetbot_deploy_node', {}, 'checkpoint')

    # --- jetbot_depth_scan: its scan's settings, and the checkpoint it takes them from ---
    def test_depth_scan_heights_out_of_order(self):
        self.refuses('jetbot_depth_scan', {'min_height': 0.6}, 'min_height = 0.6',
                     'below max_height 0.5')

    def test_depth_scan_checkpoint_of_a_laser(self):
        # The laser navigator's scan is not a depth camera's: its settings do not apply.
        self.refuses('jetbot_depth_scan', {'checkpoint': self.path_checkpoint()}, 'checkpoint',
                     "its scan_source is ''", 'camera_depth')

    def test_depth_scan_angles_out_of_order(self):
        self.refuses('jetbot_depth_scan', {}, 'angles = [1, -1]', lists={'angles': [1.0, -1.0]})

    def test_player_robot_mode_is_the_deploy_node(self):
        self.refuses('jetbot_policy_node', {'checkpoint': '/x.pt', 'robot': True},
                     'robot = (set): the robot mode is the node jetbot_deploy_node now')

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
