#!/usr/bin/python3
"""jetbot_env_node refuses to start, with a non-zero exit and a FATAL naming the culprit, when a
parameter is invalid or robot_description is missing or broken; with valid ones it starts."""
import os
import subprocess
import tempfile
import unittest

import rospkg
import rospy
import rostest

from jetbot_rl_test.ppo_test_util import node_path

RUN_TIMEOUT = 60.0  # s, for one node start-up on a loaded machine

PACKAGE = rospkg.RosPack().get_path('jetbot_rl')
URDF = open(os.path.join(PACKAGE, 'urdf', 'jetbot.urdf')).read()
TRIBOT = open(os.path.join(PACKAGE, 'urdf', 'examples', 'tribot.urdf')).read()
TRIBOT_DOFS = ['wheel_left_joint', 'wheel_right_joint']


class TestRefuseStart(unittest.TestCase):
    count = 0

    def setUp(self):
        rospy.set_param('/robot_description', URDF)

    def node_command(self, *args):
        TestRefuseStart.count += 1
        return [node_path('jetbot_env_node'),
                '__name:=refuse_%d' % TestRefuseStart.count] + list(args)

    def refuses(self, args, *texts, **params):
        """Runs the node with private params `args` ("_name:=value", typed by roscpp) and `params`
        (set on the master); it must exit non-zero with a FATAL line containing every text."""
        command = self.node_command(*args)
        name = command[1][len('__name:='):]
        for key, value in params.items():
            rospy.set_param('/%s/%s' % (name, key), value)
        proc = subprocess.run(command, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, timeout=RUN_TIMEOUT,
                              universal_newlines=True)
        self.assertNotEqual(proc.returncode, 0, proc.stdout)
        fatal = [line for line in proc.stdout.splitlines() if 'FATAL' in line]
        self.assertTrue(fatal, 'no FATAL line in:\n' + proc.stdout)
        for text in texts:
            self.assertIn(text, fatal[0], proc.stdout)
        self.assertNotIn('jetbot_env ready', proc.stdout)
        return fatal[0]

    # --- the world and the scanner: bad files and values named ---
    def test_map_file_missing(self):
        self.refuses([], 'world/map', 'no_such_map.yaml', 'cannot be read',
                     **{'world/map': '/tmp/no_such_map.yaml'})

    @staticmethod
    def map_yaml(image, fields):
        """A map YAML naming `image` with `fields` (its other lines), in a new folder; its path."""
        folder = tempfile.mkdtemp()
        with open(os.path.join(folder, 'map.yaml'), 'w') as f:
            f.write('image: %s\n%s' % (image, fields))
        return os.path.join(folder, 'map.yaml')

    def test_map_field_missing(self):
        path = self.map_yaml('map.pgm', 'origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n'
                             'free_thresh: 0.196\n')
        self.refuses([], 'world/map', "missing field 'resolution'", **{'world/map': path})

    def test_map_image_undecodable(self):
        path = self.map_yaml('map.pgm', 'resolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n'
                             'occupied_thresh: 0.65\nfree_thresh: 0.196\n')
        with open(os.path.join(os.path.dirname(path), 'map.pgm'), 'w') as f:
            f.write('not an image')
        self.refuses([], 'image', 'cannot be read as an image', **{'world/map': path})

    def test_map_thresholds_out_of_order(self):
        path = self.map_yaml(os.path.join(PACKAGE, 'maps', 'office.pgm'),
                             'resolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n'
                             'occupied_thresh: 0.3\nfree_thresh: 0.5\n')
        self.refuses([], 'free_thresh = 0.5', **{'world/map': path})

    def test_world_without_a_free_start(self):
        self.refuses([], 'world/random_start = false', **{'world/arena_size': [0.3, 0.3]})

    def test_gazebo_world_model_not_found(self):
        folder = tempfile.mkdtemp()
        path = os.path.join(folder, 'room.world')
        with open(path, 'w') as f:
            f.write('<sdf version="1.6"><world name="w"><include><uri>model://no_such_model</uri>'
                    '</include></world></sdf>\n')
        self.refuses([], 'world/gazebo_world', 'model://no_such_model',
                     **{'world/gazebo_world': path})

    def test_gazebo_world_spawn_inside_a_table_leg(self):
        self.refuses([], 'world/spawn', 'table_1::body::leg_1',
                     **{'world/gazebo_world': os.path.join(PACKAGE, 'worlds',
                                                           'furnished_room.world'),
                        'world/spawn': [-1.078, 1.697]})

    def test_scan_link_not_in_the_urdf(self):
        self.refuses([], "scan/link = 'laser'", **{'scan/link': 'laser'})

    def test_scan_angles_out_of_order(self):
        self.refuses([], 'scan/angles = [1, -1]',
                     **{'scan/link': 'base_link', 'scan/angles': [1.0, -1.0]})

    def test_scan_samples_negative(self):
        self.refuses([], 'scan/samples = -4', **{'scan/samples': -4})

    # --- parameters ---
    def test_num_envs_zero(self):
        self.refuses(['_num_envs:=0'], 'num_envs = 0')

    def test_mode_bogus(self):
        self.refuses(['_mode:=bogus'], 'mode', 'bogus')

    def test_task_unknown(self):
        self.refuses(['_task:=dance'], 'task', 'dance')

    def test_reward_variant_unknown(self):
        self.refuses(['_task:=command', '_reward_variant:=max'], 'reward_variant', 'max')

    # --- renamed parameters: the old name is refused with the new one ---
    def test_reward_renamed(self):
        self.refuses(['_task:=command', '_reward:=exp'],
                     'invalid reward = (set): was renamed reward_variant')

    def test_physics_dt_too_large(self):
        self.refuses(['_physics_dt:=0.5'], 'physics_dt = 0.5')

    def test_decimation_wrong_type(self):
        self.refuses(['_decimation:=two'], 'decimation', 'two')

    def test_negative_seed(self):
        self.refuses(['_seed:=-3'], 'seed = -3')

    def test_tf_rate_zero(self):
        self.refuses(['_tf_rate:=0.0'], 'tf_rate = 0')

    def test_real_time_factor_negative(self):
        self.refuses(['_real_time_factor:=-1.0'], 'real_time_factor = -1')

    def test_action_timeout_zero(self):
        self.refuses(['_action_timeout:=0.0'], 'action_timeout = 0')

    def test_dof_names_unknown_joint(self):
        self.refuses([], 'dof_names', 'tail_joint', dof_names=['left_wheel_joint', 'tail_joint'])

    def test_dof_names_not_a_list(self):
        self.refuses([], 'dof_names = 5', 'list of strings', dof_names=5)

    def test_publish_clock_not_bool(self):
        self.refuses([], 'publish_clock', 'bool', publish_clock='yes')

    def test_odom_rate_zero(self):
        self.refuses(['_odom_rate:=0.0'], 'odom_rate = 0')

    def test_diagnostic_period_zero(self):
        self.refuses(['_diagnostic_period:=0.0'], 'diagnostic_period = 0', 'must be in [0.01, 60]')

    def test_cmd_vel_timeout_negative(self):
        self.refuses(['_cmd_vel_timeout:=-0.5'], 'cmd_vel_timeout = -0.5')

    def test_robot_envs_was_renamed(self):
        self.refuses(['_robot_envs:=1'], 'robot_envs = (set): was renamed robot_view_envs')

    def test_robot_view_envs_negative(self):
        self.refuses(['_robot_view_envs:=-1'], 'robot_view_envs = -1')

    def test_env_prefix_dropped_with_two_robot_view_envs(self):
        self.refuses(['_num_envs:=4', '_robot_view_envs:=2', '_env_prefix:=false'],
                     'env_prefix = false', 'robot_view_envs 1, got 2')

    # --- the robot view needs a differential drive ---
    def test_robot_view_envs_without_a_differential_drive(self):
        self.refuses(['_robot_view_envs:=1'], 'robot_view_envs = 1', 'differential drive', 'dof_names',
                     dof_names=['left_wheel_joint'])

    def test_no_differential_drive_without_robot_view_envs_starts(self):
        self.starts(['_robot_view_envs:=0'], dof_names=['left_wheel_joint'])

    # --- URDFs as robot makers publish them ---
    def test_wheels_without_limit_need_the_parameter(self):
        rospy.set_param('/robot_description', TRIBOT)
        self.refuses(['_effort_limit:=0.3'], "joint 'wheel_left_joint'", 'wheel_velocity_limit',
                     dof_names=TRIBOT_DOFS)

    def test_unreadable_mesh_names_the_link_and_the_path(self):
        rospy.set_param('/robot_description', TRIBOT.replace(
            'package://jetbot_rl/urdf/examples/meshes/chassis.stl',
            'package://jetbot_rl/urdf/examples/meshes/missing.stl'))
        self.refuses(['_wheel_velocity_limit:=8.0', '_effort_limit:=0.3'], "link 'base_link'",
                     os.path.join(PACKAGE, 'urdf/examples/meshes/missing.stl'),
                     dof_names=TRIBOT_DOFS)

    def test_unknown_package_names_the_package(self):
        rospy.set_param('/robot_description', TRIBOT.replace(
            'package://jetbot_rl/', 'package://no_such_package_here/'))
        self.refuses(['_wheel_velocity_limit:=8.0', '_effort_limit:=0.3'], "link 'base_link'",
                     "package 'no_such_package_here'", dof_names=TRIBOT_DOFS)

    def test_randomization_range_inverted(self):
        self.refuses([], 'mass_scale = [1.2, 0.8]', 'min <= max', mass_scale=[1.2, 0.8])

    def test_obs_noise_std_wrong_length(self):
        # Checked against the task's observation size when the env is built.
        self.refuses([], 'parameter error', 'obs_noise_std = [0.1, 0.2]', obs_noise_std=[0.1, 0.2])

    # --- robot_description ---
    def test_robot_description_missing(self):
        rospy.delete_param('/robot_description')
        self.refuses([], 'robot_description', 'not set')

    def test_robot_description_not_xml(self):
        rospy.set_param('/robot_description', 'this is not a robot <')
        self.refuses([], 'robot_description', 'could not be parsed')

    def test_robot_description_bad_mass(self):
        start = URDF.index('<link name="left_wheel">')
        broken = URDF[:start] + URDF[start:].replace('<mass value="', '<mass value="-1', 1)
        rospy.set_param('/robot_description', broken)
        self.refuses([], 'robot_description', 'left_wheel', 'mass')

    # --- control: valid parameters start (the harness does not fail every start) ---
    def test_valid_parameters_start(self):
        self.starts(['_num_envs:=2'])

    def starts(self, args, **params):
        """Runs the node with private params `args` and `params`: it must serve ~reset."""
        command = self.node_command(*args)
        name = command[1][len('__name:='):]
        for key, value in params.items():
            rospy.set_param('/%s/%s' % (name, key), value)
        with tempfile.TemporaryFile(mode='w+') as output:
            proc = subprocess.Popen(command, stdout=output, stderr=subprocess.STDOUT)
            try:
                rospy.wait_for_service('/%s/reset' % name, RUN_TIMEOUT)
                self.assertIsNone(proc.poll(), 'the node exited after starting')
            finally:
                proc.terminate()  # SIGTERM: roscpp shuts down cleanly
                try:
                    proc.wait(timeout=RUN_TIMEOUT)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()
            output.seek(0)
            self.assertNotIn('FATAL', output.read())


if __name__ == '__main__':
    rospy.init_node('test_refuse_start')
    rostest.rosrun('jetbot_rl', 'test_refuse_start', TestRefuseStart)
