#!/usr/bin/python3
"""Closed loop, as on a robot: a shipped policy trained with domain randomisation (config/
randomization.yaml; policies/README.md) drives the env node's robot view through jetbot_deploy_node
(odometry in, cmd_vel out). Velocity task: the robot reaches >= 90 % of its top speed. Command
task: given a command on the command topic, the robot heads along it within 0.3 rad after 3 s,
and again 3 s after a new command is set while it drives."""
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

TOP_SPEED = 20.0 * 0.03  # m/s: wheel velocity limit x wheel radius


def moving(odom):
    """The robot moves (the policy drives it)."""
    return abs(odom.twist.twist.linear.x) > 0.02 or abs(odom.twist.twist.angular.z) > 0.2


class TestClosedLoop(unittest.TestCase):
    def setUp(self):
        self.odoms = EventList()
        rospy.Subscriber('/env_0/odom', Odometry, self.odoms.append)

    def drive(self, run_dir, task):
        """Starts jetbot_deploy_node on env 0's robot view."""
        return subprocess.Popen([
            'rosrun', 'jetbot_rl', 'jetbot_deploy_node', '__name:=deploy',
            '_checkpoint:=' + run_dir, '_task:=' + task,
            '_odom_topic:=/env_0/odom', '_cmd_vel_topic:=/env_0/cmd_vel',
            '_command_topic:=/robot_command',
            # no wheel parameters: the checkpoint's wheels, which the env's robot view converts
            # cmd_vel with (the trained robot's URDF)
        ])

    def odoms_after(self, start, seconds):
        """Odometry from `start` to `start + seconds` of simulation time."""
        wait_for(lambda: self.odoms and stamp(self.odoms[-1]) >= start + seconds,
                 timeout=TIMEOUT, what='odometry up to %.1f s' % (start + seconds))
        return [o for o in self.odoms if start <= stamp(o) <= start + seconds]

    def evaluate(self, *args):
        """Runs jetbot_rl_evaluate with `args`; returns (exit code, stdout, stderr)."""
        done = subprocess.run(['rosrun', 'jetbot_rl', 'jetbot_rl_evaluate'] + list(args),
                              capture_output=True, text=True, timeout=10 * TIMEOUT)
        return done.returncode, done.stdout, done.stderr

    def stop(self, proc):
        proc.send_signal(signal.SIGINT)
        self.assertEqual(proc.wait(timeout=TIMEOUT), 0)

    def test_closed_loop(self):
        task = rospy.get_param('~task')
        run_dir = rospy.get_param('~policy')
        wait_for(lambda: self.odoms, what='odometry of env 0')
        if task == 'velocity':
            count = len(self.odoms)
            proc = self.drive(run_dir, task)
            try:
                # From when the policy first moves the robot (the node's start-up, libtorch and
                # the checkpoint, takes a loaded machine seconds), past 1.5 s of speeding up.
                wait_for(lambda: any(moving(o) for o in self.odoms[count:]),
                         what='the policy to move the robot')
                t0 = stamp(next(o for o in self.odoms[count:] if moving(o)))
                motion = Motion(self.odoms_after(t0 + 1.5, 1.5))
            finally:
                self.stop(proc)
            print('closed loop, velocity task: from %.3f s: %r' % (t0 + 1.5, motion))
            print('FIGURE: closed loop, velocity task: %.3f m/s = %.1f %% of the top speed'
                  % (motion.speed, 100.0 * motion.speed / TOP_SPEED))
            self.assertGreaterEqual(motion.speed, 0.9 * TOP_SPEED)
            # The same policy on the heavier chassis on a slippery floor, in-process.
            heavy = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'config',
                                 'perturbed_heavy.yaml')
            code, out, err = self.evaluate('--checkpoint', run_dir, '--task', task,
                                           '--config', heavy, '--num-envs', '16', '--steps', '300')
            self.assertEqual(code, 0, err)
            reward = float(out.split('mean_reward_per_step=')[1].split()[0])
            print('FIGURE: jetbot_rl_evaluate, perturbed_heavy.yaml: %.4f m/s' % reward)
            self.assertGreater(reward, 0.85 * TOP_SPEED)
        else:
            target = 2.0  # rad: well to the left of the start heading (0)
            command = rospy.Publisher('/robot_command', Vector3, queue_size=1, latch=True)
            command.publish(Vector3(math.cos(target), math.sin(target), 0.0))
            count = len(self.odoms)
            proc = self.drive(run_dir, task)
            try:
                # 3 s of simulation time from when the policy first moves the robot.
                wait_for(lambda: any(moving(o) for o in self.odoms[count:]),
                         what='the policy to move the robot')
                t0 = stamp(next(o for o in self.odoms[count:] if moving(o)))
                window = self.odoms_after(t0, 3.5)
                # A new command while it drives: 3 s from when it is set (its sim time).
                turn = -1.0  # rad: to the right of the start heading, 3 rad from the first
                t1 = stamp(self.odoms[-1])
                command.publish(Vector3(math.cos(turn), math.sin(turn), 0.0))
                window_turn = self.odoms_after(t1, 3.5)
            finally:
                self.stop(proc)
            for name, start, goal, odoms in (('after the policy started', t0, target, window),
                                             ('after a new command', t1, turn, window_turn)):
                late = [o for o in odoms if stamp(o) >= start + 3.0]
                errors = [abs(math.atan2(math.sin(yaw(o.pose.pose.orientation) - goal),
                                         math.cos(yaw(o.pose.pose.orientation) - goal)))
                          for o in late]
                speed = Motion(late).speed
                print('FIGURE: closed loop, command task: heading at most %.3f rad off the '
                      'command %.1f rad 3-3.5 s %s, at %.3f m/s'
                      % (max(errors), goal, name, speed))
                self.assertLess(max(errors), 0.3, name)
                self.assertGreater(speed, 0.3, name)


if __name__ == '__main__':
    rospy.init_node('test_closed_loop')
    rostest.rosrun('jetbot_rl', 'test_closed_loop', TestClosedLoop)
