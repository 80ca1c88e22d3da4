#!/usr/bin/python3
"""Closed loop with unequal motors (docs/sim_to_real.md#policies-with-memory): two shipped
command-task policies (policies/command_memory and policies/command_motors) trained with domain
randomisation and the stock Jetbot's open-loop motors
(config/randomization.yaml, config/jetbot_motors.yaml), one with memory
(config/ppo_command_memory.yaml) and one without (config/ppo_command.yaml), drive through
jetbot_deploy_node two realtime envs: `weak`, whose right motor is 20 % weaker than
its left, with a dead zone, a heavier chassis on a slippery floor and 2 steps of delay
(config/perturbed_weak_motor.yaml), and `nominal`. Each gets a command to the left, then one to the
right while it drives. 4 s after each, the policy with memory heads within 0.1 rad of it at
>= 0.4 m/s on the weak robot, and no worse than that on the nominal one; the memoryless policy's
offsets are printed beside it. The exported policy with memory runs in a bare Python."""
import math
import os
import signal
import subprocess
import unittest

import rospkg
import rospy
import rostest
from geometry_msgs.msg import Vector3
from nav_msgs.msg import Odometry

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for
from jetbot_rl_test.robot_view_client import Motion, stamp, yaw

COMMANDS = (2.0, -1.0)  # rad: to the left of the start heading, then to the right
SETTLE = 4.0            # s of simulation time from a command to the measurement
WINDOW = 0.5            # s measured
ROBOTS = ('weak', 'nominal')

# Run by a bare /usr/bin/python3: only torch and yaml.
EXPORT_CHECK = """
import torch, yaml
extra = {'meta.yaml': ''}
policy = torch.jit.load(%r, _extra_files=extra)
meta = yaml.safe_load(extra['meta.yaml'])
assert meta['memory'] is True, meta
torch.manual_seed(0)
steps, shift = 20, 8
obs = torch.randn(steps, 1, meta['obs_dim'])
hidden = policy.initial_hidden(2)
assert hidden.shape == (2, meta['hidden_size']) and bool((hidden == 0).all()), hidden.shape
low, high = torch.tensor(meta['action_low']), torch.tensor(meta['action_high'])
actions = []
for t in range(steps):
    if t == shift:
        hidden[1] = 0.0  # env 1 starts over
    row1 = obs[t - shift] if t >= shift else obs[(t * 7) %% steps]
    a, hidden = policy(torch.cat([obs[t], row1]), hidden)
    assert a.shape == (2, meta['action_dim']) and bool(((a >= low) & (a <= high)).all()), a
    actions.append(a)
for j in range(steps - shift):
    assert torch.equal(actions[shift + j][1], actions[j][0]), (j, actions[shift + j], actions[j])
fresh, _ = policy(obs[steps - 1], policy.initial_hidden(1))
assert not torch.equal(fresh[0], actions[steps - 1][0]), 'carried memory changes nothing'
print('export check passed: hidden_size %%d, %%d steps' %% (meta['hidden_size'], steps))
"""


def heading_error(odom, command):
    d = yaw(odom.pose.pose.orientation) - command
    return abs(math.atan2(math.sin(d), math.cos(d)))


def moving(odom):
    return abs(odom.twist.twist.linear.x) > 0.02 or abs(odom.twist.twist.angular.z) > 0.2


class TestClosedLoopMemory(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.odoms = {robot: EventList() for robot in ROBOTS}
        for robot in ROBOTS:
            rospy.Subscriber('/%s/env_0/odom' % robot, Odometry, cls.odoms[robot].append)
        cls.commands = {robot: rospy.Publisher('/%s_command' % robot, Vector3, queue_size=1,
                                               latch=True) for robot in ROBOTS}
        policies = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies')
        cls.runs = {'memory': os.path.join(policies, 'command_memory'),
                    'memoryless': os.path.join(policies, 'command_motors')}

    def window(self, robot, start):
        """Odometry of `robot` from `start` + SETTLE for WINDOW s of simulation time."""
        odoms = self.odoms[robot]
        end = start + SETTLE + WINDOW
        wait_for(lambda: odoms and stamp(odoms[-1]) >= end, timeout=TIMEOUT,
                 what='%s odometry up to %.1f s' % (robot, end))
        return [o for o in odoms if start + SETTLE <= stamp(o) <= end]

    def drive(self, policy):
        """Drives both robots at once (two env nodes, a deploy node each) with `policy` through
        COMMANDS; returns {robot: [(largest heading error [rad], speed [m/s])]} over each
        command's window."""
        counts, procs = {}, {}
        for robot in ROBOTS:
            wait_for(lambda: self.odoms[robot], what='odometry of %s' % robot)
            self.commands[robot].publish(Vector3(math.cos(COMMANDS[0]), math.sin(COMMANDS[0]),
                                                 0.0))
            counts[robot] = len(self.odoms[robot])
        try:
            for robot in ROBOTS:
                procs[robot] = subprocess.Popen([
                    'rosrun', 'jetbot_rl', 'jetbot_deploy_node',
                    '__name:=%s_%s' % (policy, robot), '_checkpoint:=' + self.runs[policy],
                    '_odom_topic:=/%s/env_0/odom' % robot,
                    '_cmd_vel_topic:=/%s/env_0/cmd_vel' % robot,
                    '_command_topic:=/%s_command' % robot,
                    # no wheel parameters: the checkpoint's wheels, which the env's robot view
                    # converts cmd_vel with (the trained robot's URDF)
                ])
            # The first command counts from when the policy first moves the robot; the second
            # from when it is set, while the robot drives.
            starts, results = {}, {robot: [] for robot in ROBOTS}
            for robot in ROBOTS:
                odoms, count = self.odoms[robot], counts[robot]
                wait_for(lambda: any(moving(o) for o in odoms[count:]),
                         what='%s to move %s' % (policy, robot))
                starts[robot] = stamp(next(o for o in odoms[count:] if moving(o)))
            for k, goal in enumerate(COMMANDS):
                for robot in ROBOTS:
                    if k > 0:
                        starts[robot] = stamp(self.odoms[robot][-1])
                        self.commands[robot].publish(Vector3(math.cos(goal), math.sin(goal), 0.0))
                for robot in ROBOTS:
                    window = self.window(robot, starts[robot])
                    results[robot].append((max(heading_error(o, goal) for o in window),
                                           Motion(window).speed))
        finally:
            for proc in procs.values():
                proc.send_signal(signal.SIGINT)
            for proc in procs.values():
                self.assertEqual(proc.wait(timeout=TIMEOUT), 0)
        for robot in ROBOTS:
            for goal, (error, speed) in zip(COMMANDS, results[robot]):
                print('FIGURE: closed loop, %s robot, %s policy: heading at most %.3f rad off the '
                      'command %.1f rad %.1f-%.1f s after it, at %.3f m/s'
                      % (robot, policy, error, goal, SETTLE, SETTLE + WINDOW, speed))
        return results

    def test_exported_policy_runs_in_python_without_the_package(self):
        """The memory policy's exported/policy.pt, loaded by a bare Python (no ROS, no package on
        any path) as docs/sim_to_real.md#export shows: forward(obs, hidden) -> (actions, hidden);
        each row is an env of its own; a row zeroed midway starts over exactly (its actions
        equal a fresh env's on the same inputs), and carried memory changes the actions."""
        script = EXPORT_CHECK % os.path.join(self.runs['memory'], 'exported', 'policy.pt')
        out = subprocess.run(['/usr/bin/python3', '-c', script], env={'PATH': '/usr/bin:/bin'},
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=60 * TIMEOUT)
        print(out.stdout)
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertIn('export check passed', out.stdout)

    def test_memory_absorbs_a_weak_motor(self):
        figures = {}
        for policy in ('memoryless', 'memory'):
            for robot, results in self.drive(policy).items():
                figures[policy, robot] = results
        for robot in ROBOTS:
            for (error, speed), goal in zip(figures['memory', robot], COMMANDS):
                self.assertLess(error, 0.1, '%s robot, command %.1f rad' % (robot, goal))
                self.assertGreaterEqual(speed, 0.4, '%s robot, command %.1f rad' % (robot, goal))
        # The contrast: without memory the weak motor leaves a larger offset.
        worst = max(error for error, _ in figures['memoryless', 'weak'])
        self.assertGreater(worst, max(error for error, _ in figures['memory', 'weak']))


if __name__ == '__main__':
    rospy.init_node('test_closed_loop_memory')
    rostest.rosrun('jetbot_rl', 'test_closed_loop_memory', TestClosedLoopMemory)
