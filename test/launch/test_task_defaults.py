#!/usr/bin/python3
"""Each task's defaults live in one place: launch/jetbot_env.launch picks the robot (urdf) and the
task's env file (task_config) from `task` when they are left empty, and every launch file that
starts an env passes them through. Compared on the parameters roslaunch would set (what
`roslaunch --dump-params` prints, read in-process through the same roslaunch loader; no master): `jetbot_env.launch task:=navigation` is the env that
`train.launch task:=navigation` trains (env node, several nodes, in-process), that play.launch,
env_host.launch and view.launch start; a urdf or task_config given wins."""
import os
import unittest

import roslaunch.config
import roslaunch.rlutil
import rospkg
import rostest
import yaml

PKG = rospkg.RosPack().get_path('jetbot_rl')
NAV_URDF = os.path.join(PKG, 'urdf', 'jetbot_lidar.urdf')
NAV_ENV = os.path.join(PKG, 'config', 'navigation_env.yaml')
NAV_WORLD = os.path.join(PKG, 'config', 'world_generated.yaml')
JETBOT_URDF = os.path.join(PKG, 'urdf', 'jetbot.urdf')
BASE_ENV = os.path.join(PKG, 'config', 'jetbot_env.yaml')
# Parameters a launch file sets for its purpose (how the env runs, not which env it is):
# train.launch a training run's (2 stepping threads, nobody watching), play.launch and view.launch
# a watched one's, env_nodes.launch each node's prefix.
RUN_PARAMS = {'num_envs', 'num_threads', 'mode', 'seed', 'publish_clock', 'tf_envs', 'robot_view_envs',
              'real_time_factor', 'robot_prefix'}


def dump(launch_file, *args):
    """The parameters `roslaunch jetbot_rl launch_file args` would set: {name: value}, as
    `roslaunch --dump-params` loads them (without a process per launch file)."""
    path = roslaunch.rlutil.resolve_launch_arguments(['jetbot_rl', launch_file])[0]
    config = roslaunch.config.load_config_default([(path, list(args))], None, verbose=False)
    return {name: param.value for name, param in config.params.items()}


def under(params, ns):
    """The parameters in namespace `ns` (e.g. /jetbot_env), by their name in it."""
    prefix = ns.rstrip('/') + '/'
    return {k[len(prefix):]: v for k, v in params.items() if k.startswith(prefix)}


def text(path):
    with open(path) as f:
        return f.read()


def file_params(path):
    """The parameters a YAML file sets, named as the node reads them (world/arena_size, ...)."""
    def flat(tree, prefix=''):
        out = {}
        for key, value in tree.items():
            if isinstance(value, dict):
                out.update(flat(value, prefix + key + '/'))
            else:
                out[prefix + key] = value
        return out
    with open(path) as f:
        return flat(yaml.safe_load(f))


class TestTaskDefaults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.nav = dump('jetbot_env.launch', 'task:=navigation')
        cls.nav_env = under(cls.nav, '/jetbot_env')

    def assertSameEnv(self, env, what, also_differ=()):
        """`env` (a node's parameters) is the navigation env of jetbot_env.launch, but for the
        run parameters (and `also_differ`)."""
        allowed = RUN_PARAMS | set(also_differ)
        keys = set(env) | set(self.nav_env)
        differ = sorted(k for k in keys if env.get(k, '<unset>') != self.nav_env.get(k, '<unset>'))
        self.assertEqual([k for k in differ if k not in allowed], [],
                         '%s sets another env than jetbot_env.launch task:=navigation: %s'
                         % (what, ', '.join('%s = %r, not %r' % (k, env.get(k, '<unset>'),
                                                                 self.nav_env.get(k, '<unset>'))
                                            for k in differ if k not in allowed)))

    def test_navigation_defaults_of_jetbot_env_launch(self):
        """task:=navigation alone: the lidar Jetbot, config/navigation_env.yaml and the generated
        worlds of config/world_generated.yaml, as given explicitly."""
        self.assertEqual(self.nav['/robot_description'], text(NAV_URDF))
        self.assertEqual(self.nav_env['task'], 'navigation')
        for key, value in list(file_params(NAV_ENV).items()) + list(file_params(NAV_WORLD).items()):
            self.assertEqual(self.nav_env[key], value, key)
        self.assertEqual(self.nav, dump('jetbot_env.launch', 'task:=navigation',
                                        'urdf:=' + NAV_URDF, 'task_config:=' + NAV_ENV,
                                        'world:=' + NAV_WORLD))

    def test_a_world_of_ones_own_replaces_the_generated_worlds(self):
        """A map, a Gazebo world or a world file given: no generated layouts with it (the core
        refuses families beside a map), the task's env file still loaded."""
        office = os.path.join(PKG, 'maps', 'office.yaml')
        obstacles = os.path.join(PKG, 'config', 'world_obstacles.yaml')
        room = os.path.join(PKG, 'worlds', 'furnished_room.world')
        for arg, own in (('map:=' + office, {}), ('world:=' + obstacles, file_params(obstacles)),
                         ('gazebo_world:=' + room, {})):
            env = under(dump('jetbot_env.launch', 'task:=navigation', arg), '/jetbot_env')
            self.assertNotIn('world/families', env, arg)
            self.assertNotIn('world/curriculum', env, arg)
            for key, value in dict(file_params(NAV_ENV), **own).items():
                self.assertEqual(env[key], value, '%s: %s' % (arg, key))  # the world file wins

    def test_train_launch_trains_that_env(self):
        train = dump('train.launch', 'task:=navigation')
        self.assertEqual(train['/robot_description'], text(NAV_URDF))
        self.assertEqual(train['/jetbot_ppo_trainer/env_nodes'], 'jetbot_env')
        self.assertSameEnv(under(train, '/jetbot_env'), 'train.launch task:=navigation')
        # the env in the trainer's process gets the same parameters in its ~env_config
        in_process = dump('train.launch', 'task:=navigation', 'in_process:=true')
        self.assertEqual(in_process['/robot_description'], text(NAV_URDF))
        self.assertEqual(under(in_process, '/jetbot_env'), {})
        self.assertSameEnv(under(in_process, '/jetbot_ppo_trainer/env_config'),
                           'train.launch task:=navigation in_process:=true')

    def test_train_launch_trains_the_navigators_mix(self):
        """task:=navigation mix:=true: the three parts of launch/navigation_mix.launch, as env nodes
        or under the trainer's ~env_config/NAME: the generated worlds of jetbot_env.launch
        task:=navigation with navigation_mix_worlds.yaml over them, the same with
        navigation_mix_team.yaml, and the swap with the navigator's observation; all parts agree
        on what the batch needs alike (the speed limit too: applied in the worlds, named in the
        team's and the swap's spec)."""
        parts = ['jetbot_env_worlds', 'jetbot_env_team', 'jetbot_env_swap']
        worlds = file_params(os.path.join(PKG, 'config', 'navigation_mix_worlds.yaml'))
        team = file_params(os.path.join(PKG, 'config', 'navigation_mix_team.yaml'))
        swap_files = [os.path.join(PKG, 'config', f)
                      for f in ('navigation_swap.yaml', 'navigation_mix_swap.yaml')]
        swap = dict(file_params(swap_files[0]), **file_params(swap_files[1]))
        in_process = '/jetbot_ppo_trainer/env_config/'
        for args, prefix in (([], in_process), (['nodelet:=true'], in_process),
                             (['in_process:=false'], '/'),
                             (['in_process:=false', 'nodelet:=true'], '/')):
            what = 'train.launch task:=navigation mix:=true ' + ' '.join(args)
            params = dump('train.launch', 'task:=navigation', 'mix:=true', *args)
            self.assertTrue(params['/jetbot_ppo_trainer/iterations'] > 0, what)
            self.assertEqual(params['/jetbot_ppo_trainer/max_learning_rate'], 0.0005, what)
            self.assertEqual(params['/robot_description'], text(NAV_URDF), what)
            self.assertEqual(params['/jetbot_ppo_trainer/env_nodes'], parts, what)
            self.assertEqual(under(params, '/jetbot_env'), {}, what)
            self.assertEqual(params['/jetbot_ppo_trainer/env_in_process'], prefix == in_process,
                             what)
            envs = {p: under(params, prefix + p) for p in parts}
            self.assertSameEnv(envs['jetbot_env_worlds'], what + ': worlds', also_differ=worlds)
            for key, value in worlds.items():
                self.assertEqual(envs['jetbot_env_worlds'][key], value,
                                 '%s: worlds %s' % (what, key))
            self.assertEqual(envs['jetbot_env_worlds']['num_envs'], 24, what)
            self.assertSameEnv(envs['jetbot_env_team'], what + ': team', also_differ=team)
            for key, value in team.items():
                self.assertEqual(envs['jetbot_env_team'][key], value, '%s: team %s' % (what, key))
            for key, value in swap.items():
                self.assertEqual(envs['jetbot_env_swap'][key], value, '%s: swap %s' % (what, key))
            self.assertNotIn('world/families', envs['jetbot_env_swap'], what)
            # every part's checkpoint spec must name the limit alike: applied in the worlds,
            # only named (deployed) among people and robots
            self.assertIs(envs['jetbot_env_worlds'].get('speed_limit/enabled'), True, what)
            for part in parts[1:]:
                where = '%s: %s' % (what, part)
                self.assertIs(envs[part].get('speed_limit/deployed'), True, where)
                self.assertIsNot(envs[part].get('speed_limit/enabled'), True, where)
            for key in ('task', 'decimation', 'episode_length_s', 'action_space',
                        'twist_reverse_speed', 'scan/samples', 'scan/angles', 'scan/range',
                        'nav/beams', 'nav/path', 'nav/path_lookahead', 'nav/log_beams'):
                self.assertEqual(envs['jetbot_env_swap'].get(key), self.nav_env.get(key),
                                 '%s: the swap part differs in %s' % (what, key))
        # num_envs sizes the generated worlds; what the mix cannot honour ends the launch naming it
        self.assertEqual(dump('train.launch', 'task:=navigation', 'mix:=true', 'num_envs:=7')
                         [in_process + 'jetbot_env_worlds/num_envs'], 7)
        for args in (['task:=command'],
                     ['task:=navigation', 'map:=' + os.path.join(PKG, 'maps', 'office.yaml')],
                     ['task:=navigation', 'num_env_nodes:=2'], ['task:=navigation', 'x_pos:=0'],
                     ['task:=navigation', 'task_config:=' + NAV_ENV]):
            with self.assertRaises(Exception) as refused:
                dump('train.launch', 'mix:=true', *args)
            self.assertIn('mix:=true_takes_only_task:=navigation', str(refused.exception), args)
        # several env nodes, and env nodes on another host
        for launch_file, args in (('train.launch', ['num_env_nodes:=2']),
                                  ('env_host.launch', ['num_env_nodes:=2'])):
            params = dump(launch_file, 'task:=navigation', *args)
            self.assertEqual(params['/robot_description'], text(NAV_URDF))
            for k in range(2):
                self.assertSameEnv(under(params, '/jetbot_env_%d' % k),
                                   '%s task:=navigation %s' % (launch_file, ' '.join(args)))

    def test_play_and_view_launch_start_that_env(self):
        for launch_file, args in (('play.launch', ['checkpoint:=x']), ('view.launch', [])):
            params = dump(launch_file, 'task:=navigation', *args)
            self.assertEqual(params['/robot_description'], text(NAV_URDF), launch_file)
            self.assertSameEnv(under(params, '/jetbot_env'), launch_file + ' task:=navigation')

    def test_the_start_wherever_a_gazebo_world_is_offered(self):
        """x_pos, y_pos and yaw (docs/world.md's TurtleBot3 world start) reach every env node of
        every launch file that offers gazebo_world:=, as world/spawn and initial_yaw."""
        start = ['x_pos:=-2.0', 'y_pos:=-0.5', 'yaw:=1.5']
        for launch_file, args, nodes in (
                ('jetbot_env.launch', [], ['/jetbot_env']),
                ('train.launch', [], ['/jetbot_env']),
                ('train.launch', ['in_process:=true'], ['/jetbot_ppo_trainer/env_config']),
                ('train.launch', ['num_env_nodes:=2'], ['/jetbot_env_0', '/jetbot_env_1']),
                ('env_host.launch', ['num_env_nodes:=2'], ['/jetbot_env_0', '/jetbot_env_1']),
                ('play.launch', ['checkpoint:=x'], ['/jetbot_env'])):
            params = dump(launch_file, *(args + start))
            for node in nodes:
                env = under(params, node)
                what = '%s %s: %s' % (launch_file, ' '.join(args + start), node)
                self.assertEqual(env.get('world/spawn'), [-2.0, -0.5], what)
                self.assertEqual(env.get('initial_yaw'), [1.5, 1.5], what)
            # without them, the parameters' start
            env = under(dump(launch_file, *args), nodes[0])
            self.assertNotEqual(env.get('world/spawn'), [-2.0, -0.5], launch_file)

    def assertNoTaskFile(self, env, what, but=()):
        """`env` holds none of navigation_env.yaml's settings (but those of `but`): its keys that
        config/jetbot_env.yaml sets have that file's values, the others are unset."""
        base = file_params(BASE_ENV)
        for key in (set(file_params(NAV_ENV)) | set(file_params(NAV_WORLD))) - set(but):
            if key in base:
                self.assertEqual(env[key], base[key], '%s: %s' % (what, key))
            else:
                self.assertNotIn(key, env, '%s loads %s of navigation_env.yaml' % (what, key))

    def test_road_following_defaults_of_jetbot_env_launch(self):
        """task:=road_following alone: the camera Jetbot and config/road_following_env.yaml, no
        world; the same as given explicitly."""
        road_urdf = os.path.join(PKG, 'urdf', 'jetbot_camera.urdf')
        road_env = os.path.join(PKG, 'config', 'road_following_env.yaml')
        params = dump('jetbot_env.launch', 'task:=road_following')
        env = under(params, '/jetbot_env')
        self.assertEqual(params['/robot_description'], text(road_urdf))
        self.assertEqual(env['task'], 'road_following')
        for key, value in file_params(road_env).items():
            self.assertEqual(env[key], value, key)
        self.assertFalse([k for k in env if k.startswith('world/')], 'a world was loaded')
        self.assertEqual(params, dump('jetbot_env.launch', 'task:=road_following',
                                      'urdf:=' + road_urdf, 'task_config:=' + road_env))

    def test_other_tasks_keep_the_jetbot_without_a_task_file(self):
        for launch_file, args in (('jetbot_env.launch', []), ('jetbot_env.launch', ['task:=command']),
                                  ('train.launch', []), ('train.launch', ['task:=command']),
                                  ('play.launch', ['checkpoint:=x']), ('view.launch', [])):
            params = dump(launch_file, *args)
            what = '%s %s' % (launch_file, ' '.join(args))
            self.assertEqual(params['/robot_description'], text(JETBOT_URDF), what)
            self.assertNoTaskFile(under(params, '/jetbot_env'), what)

    def test_given_urdf_and_task_config_win(self):
        tribot = os.path.join(PKG, 'urdf', 'examples', 'tribot.urdf')
        other = os.path.join(PKG, 'config', 'navigation_robot.yaml')
        expected = file_params(other)
        self.assertNotEqual({k: self.nav_env.get(k) for k in expected}, expected,
                            'the test needs a task file that differs from navigation_env.yaml')
        for launch_file, args in (('jetbot_env.launch', []), ('train.launch', []),
                                  ('train.launch', ['in_process:=true']),
                                  ('play.launch', ['checkpoint:=x'])):
            params = dump(launch_file, 'task:=navigation', 'urdf:=' + tribot,
                          'task_config:=' + other, *args)
            what = '%s %s' % (launch_file, ' '.join(args))
            self.assertEqual(params['/robot_description'], text(tribot), what)
            ns = '/jetbot_ppo_trainer/env_config' if args == ['in_process:=true'] else '/jetbot_env'
            env = under(params, ns)
            for key, value in expected.items():
                self.assertEqual(env[key], value, '%s: %s' % (what, key))
            self.assertNoTaskFile(env, what, but=expected)

    def test_a_former_argument_reaches_the_node_which_refuses_it(self):
        # roslaunch ignores an argument no launch file declares: robot_envs (now robot_view_envs)
        # is declared and passed on, so that the node ends start-up naming the new name
        # (test_refuse_start.py checks the refusal).
        env = under(dump('jetbot_env.launch', 'robot_envs:=2'), '/jetbot_env')
        self.assertEqual(env['robot_envs'], '2')
        self.assertNotIn('robot_envs', under(dump('jetbot_env.launch'), '/jetbot_env'))


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_task_defaults', TestTaskDefaults)
