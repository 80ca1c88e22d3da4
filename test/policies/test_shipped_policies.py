#!/usr/bin/python3
"""The shipped policies (policies/README.md) still load and act as their figures say: each is
played by jetbot_rl_evaluate on the env it was trained for (which it must fit), on seeds not used
in training, and
its figures must reach the bar that README gives (printed as FIGURE lines)."""
import os
import re
import subprocess
import unittest

import rospkg
import rostest

PKG = rospkg.RosPack().get_path('jetbot_rl')
POLICIES = os.path.join(PKG, 'policies')


def config(name):
    return os.path.join(PKG, 'config', name)


LIDAR = ['--urdf', os.path.join(PKG, 'urdf', 'jetbot_lidar.urdf'), '--config',
         config('jetbot_env.yaml')]
# the task's env file as train.launch's task_config gave it (navigation_env.yaml by default)
NAVIGATION = LIDAR + ['--task', 'navigation', '--steps', '100000']
# name: (jetbot_rl_evaluate arguments, {figure: (at least, at most)})
CASES = {
    'velocity': (['--task', 'velocity', '--num-envs', '16', '--steps', '300', '--seed', '123'],
                 {'mean_reward_per_step': (0.54, None)}),
    'command': (['--task', 'command', '--num-envs', '16', '--steps', '600', '--seed', '123'],
                {'mean_reward_per_step': (1.3, None)}),
    # on the weak robot of closed_loop_memory.test (unequal motors, dead zone, heavier, delayed)
    'command_memory': (['--task', 'command', '--config', config('jetbot_motors.yaml'), '--config',
                        config('perturbed_weak_motor.yaml'), '--num-envs', '16', '--steps', '600',
                        '--seed', '123'],
                       {'mean_reward_per_step': (1.15, None)}),
    'command_motors': (['--task', 'command', '--config', config('jetbot_motors.yaml'),
                        '--num-envs', '16', '--steps', '600', '--seed', '123'],
                       {'mean_reward_per_step': (1.3, None)}),
    'navigation': (NAVIGATION + ['--config', config('navigation_env.yaml'), '--config',
                                 config('world_generated.yaml'), '--num-envs', '50',
                                 '--episodes', '200', '--seed', '5000'],
                   {'success_rate': (0.95, None), 'collision_rate': (None, 0.02)}),
    'navigation_arena': (NAVIGATION + ['--config', config('navigation_arena.yaml'),
                                       '--num-envs', '50', '--episodes', '200', '--seed', '5000'],
                         {'success_rate': (0.95, None), 'collision_rate': (None, 0.03)}),
    'people': (NAVIGATION + ['--config', config('navigation_people.yaml'), '--num-envs', '50',
                             '--episodes', '400', '--seed', '123'],
               {'success_rate': (0.93, None), 'collision_rate': (None, 0.07)}),
    'swap': (NAVIGATION + ['--config', config('navigation_swap.yaml'), '--num-envs', '5',
                           '--episodes', '200', '--seed', '123'],
             {'success_rate': (0.93, None), 'collision_rate': (None, 0.07)}),
    # the mix's navigator in the 20-robot swap, as its mix's swap part holds it (the navigator's
    # observation, 20 s episodes), behind the speed limit its checkpoint names
    'navigation_mix': (NAVIGATION + ['--config', config('navigation_swap.yaml'), '--config',
                                     config('navigation_mix_swap.yaml'), '--num-envs', '5',
                                     '--episodes', '400', '--seed', '123'],
                       {'success_rate': (0.95, None), 'collision_rate': (None, 0.02)}),
    # the camera's depth as its scan (the forward field of view only), in the generated worlds
    'navigation_camera': (['--urdf', os.path.join(PKG, 'urdf', 'jetbot_camera.urdf'), '--config',
                           config('jetbot_env.yaml'), '--task', 'navigation', '--steps', '100000',
                           '--config', config('navigation_camera_env.yaml'), '--config',
                           config('world_generated.yaml'), '--num-envs', '25', '--episodes',
                           '50', '--seed', '5000'],
                          {'success_rate': (0.9, None), 'collision_rate': (None, 0.05)}),
    # from the camera alone, on tracks, colours and light of seeds not used in training
    'road_following': (['--urdf', os.path.join(PKG, 'urdf', 'jetbot_camera.urdf'), '--config',
                        config('jetbot_env.yaml'), '--config', config('road_following_env.yaml'),
                        '--task', 'road_following', '--num-envs', '25', '--episodes', '50',
                        '--steps', '100000', '--seed', '777'],
                       {'success_rate': (0.95, None), 'off_track_rate': (None, 0.03)}),
}


class TestShippedPolicies(unittest.TestCase):
    def check(self, name):
        args, bars = CASES[name]
        done = subprocess.run(['rosrun', 'jetbot_rl', 'jetbot_rl_evaluate', '--checkpoint',
                               os.path.join(POLICIES, name)] + args,
                              capture_output=True, text=True, timeout=600)
        # A policy that does not fit its env (observations, actions) exits 1 naming the field.
        self.assertEqual(done.returncode, 0, done.stderr)
        figures = dict(re.findall(r'(\w+)=([-+0-9.eE]+)', done.stdout))
        for figure, (low, high) in bars.items():
            self.assertIn(figure, figures, done.stdout)
            value = float(figures[figure])
            print('FIGURE: policies/%s: %s = %.4f' % (name, figure, value))
            if low is not None:
                self.assertGreaterEqual(value, low, '%s %s' % (name, figure))
            if high is not None:
                self.assertLessEqual(value, high, '%s %s' % (name, figure))

    def test_every_policy_is_tested(self):
        shipped = sorted(d for d in os.listdir(POLICIES)
                         if os.path.isdir(os.path.join(POLICIES, d)))
        self.assertEqual(shipped, sorted(CASES))


for _name in CASES:
    setattr(TestShippedPolicies, 'test_' + _name,
            lambda self, name=_name: self.check(name))

if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'shipped_policies', TestShippedPolicies)
