#!/usr/bin/python3
"""The robot view's cmd_vel, read back through odom. One scenario per .test, chosen by the private
parameter `case`:
  drive     realtime: straight at r * omega (within 5 %), in place at 2 omega r / separation
            (within 10 %), beyond the wheel limit with the curvature kept (within 10 %), the
            other env untouched, cmd_vel over WheelTargets for its own env only; the kinematics
            in ~spec equal `wheel_radius` / `wheel_separation`
  lockstep  cmd_vel is rejected, counted in /diagnostics, and never moves the robot
  brake     realtime: cmd_vel drives until it is cmd_vel_timeout old, then the robot brakes
  nan       realtime: a Twist with NaN or Inf is rejected and counted; the previous command stays
"""
import math
import time
import unittest

import rospy
import rostest

from jetbot_rl.msg import EnvSpec, WheelTargets
from jetbot_rl_test.env_client import NODE, TIMEOUT, EnvClient, wait_for
from jetbot_rl_test.robot_view_client import DRIVE_CADENCE, Diagnostics, Motion, RobotView, twist


def spec():
    return rospy.wait_for_message(NODE + '/spec', EnvSpec, TIMEOUT)


class TestDrive(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.spec = spec()
        cls.r = cls.spec.wheel_radius
        cls.sep = cls.spec.wheel_separation
        cls.limit = cls.spec.action_high[0]
        cls.omega = 0.5 * cls.limit  # wheel speed of the tests [rad/s]
        cls.env0 = RobotView('/env_0/')
        cls.env1 = RobotView('/env_1/')

    def test_1_kinematics_in_spec(self):
        self.assertAlmostEqual(self.r, rospy.get_param('~wheel_radius'), places=6)
        self.assertAlmostEqual(self.sep, rospy.get_param('~wheel_separation'), places=6)

    def test_2_straight_at_r_omega(self):
        v = self.omega * self.r
        m = self.env0.measure(twist(v, 0.0))
        print('straight, commanded %.4f m/s: %s' % (v, m))
        self.assertLess(abs(m.forward - v), 0.05 * v, m)
        self.assertLess(abs(m.twist_linear - v), 0.05 * v, m)
        self.assertLess(abs(m.yaw_rate), 0.05, m)
        # env 1 got no cmd_vel (and no WheelTargets): it stands where it started
        p = self.env1.odom[-1].pose.pose.position
        self.assertLess(math.hypot(p.x, p.y), 0.01, 'env 1 moved')
        self.assertEqual(self.env1.odom[-1].header.frame_id, 'env_1/odom')

    def test_3_turn_in_place_at_2_omega_r_over_separation(self):
        w = 2.0 * self.omega * self.r / self.sep
        m = self.env0.measure(twist(0.0, w))
        print('in place, commanded %.4f rad/s: %s' % (w, m))
        self.assertLess(abs(m.yaw_rate - w), 0.10 * w, m)
        self.assertLess(abs(m.twist_angular - w), 0.10 * w, m)
        self.assertLess(m.speed, 0.1 * self.omega * self.r, m)  # the axle's middle stays put

    def test_4_beyond_the_wheel_limit_the_curvature_stays(self):
        v = 2.0 * self.limit * self.r  # twice the top speed, on a 0.5 m radius
        w = v / 0.5
        m = self.env0.measure(twist(v, w))
        print('beyond the limit, commanded %.4f m/s, %.4f rad/s: %s' % (v, w, m))
        self.assertLess(abs(m.yaw_rate / m.speed - w / v), 0.10 * w / v, m)
        self.assertLess(m.speed, 1.02 * self.limit * self.r, m)  # scaled down
        self.assertGreater(m.speed, 0.5 * self.limit * self.r, m)

    def test_5_cmd_vel_wins_over_wheel_targets_for_its_env_only(self):
        pub = rospy.Publisher(NODE + '/wheel_targets', WheelTargets, queue_size=10)
        wait_for(lambda: pub.get_num_connections() > 0, what='the node to subscribe',
                 recheck=0.05)
        # WheelTargets: both envs forward; cmd_vel: env 0 backwards
        targets = WheelTargets(velocities=[self.omega] * 4)
        odom1 = len(self.env1.odom)
        v = self.omega * self.r
        m0 = self.env0.measure(twist(-v, 0.0), also=lambda: pub.publish(targets))
        m1 = Motion(self.env1.odom[odom1:][-40:])
        print('cmd_vel backwards over WheelTargets forwards: env 0 %s, env 1 %s' % (m0, m1))
        self.assertLess(abs(m0.forward + v), 0.05 * v, m0)
        self.assertLess(abs(m1.forward - v), 0.05 * v, m1)


class TestLockstep(unittest.TestCase):
    def test_cmd_vel_rejected_and_counted(self):
        client = EnvClient()
        diagnostics = Diagnostics()
        view = RobotView('/env_0/', wait_state=False)
        start = client.current().step
        # a teleop keeps publishing: every message is rejected, counted, and steps nothing
        deadline = time.monotonic() + TIMEOUT
        counted = lambda d: int(d['rejected cmd_vel']) >= 3  # noqa: E731
        while diagnostics.find(counted) is None:
            view.cmd.publish(twist(0.3, 0.0))
            time.sleep(DRIVE_CADENCE)
            self.assertLess(time.monotonic(), deadline, 'no cmd_vel rejections counted')
        status = diagnostics.find(counted)
        self.assertIn('lockstep mode steps only with WheelTargets',
                      status['last cmd_vel rejection reason'])
        self.assertEqual(client.current().step, start, 'cmd_vel stepped the env')
        # stepping with zero WheelTargets while cmd_vel keeps coming: the robot stays put
        step = start
        for _ in range(60):
            view.cmd.publish(twist(0.3, 0.0))
            step = client.step_topic(step, [0.0] * 2).step
        wait_for(lambda: view.odom and view.odom[-1].header.stamp > rospy.Time(0.9),
                 what='odom of the lockstep steps')
        p = view.odom[-1].pose.pose.position
        self.assertLess(math.hypot(p.x, p.y), 0.005, 'cmd_vel moved the robot in lockstep mode')
        self.assertLess(abs(view.odom[-1].twist.twist.linear.x), 0.01)


class TestBrake(unittest.TestCase):
    def test_drives_until_cmd_vel_timeout_then_brakes(self):
        view = RobotView('/env_0/')
        limit = spec().action_high[0]
        v = 0.5 * limit * spec().wheel_radius
        m = view.measure(twist(v, 0.0), settle=1.0, seconds=0.5)
        self.assertLess(abs(m.forward - v), 0.05 * v, m)
        last = len(view.odom)
        # no more cmd_vel: the next odom messages still drive (cmd_vel_timeout 0.5 s) ...
        wait_for(lambda: len(view.odom) >= last + 5, what='odom after the last cmd_vel')
        after = [o.twist.twist.linear.x for o in view.odom[last:last + 5]]
        self.assertGreater(min(after), 0.8 * v, 'braked before cmd_vel_timeout: %s' % after)
        # ... then the robot brakes to a stop
        wait_for(lambda: abs(view.odom[-1].twist.twist.linear.x) < 0.005,
                 what='the robot to brake after cmd_vel_timeout')
        view.wait_sim(0.5)
        self.assertLess(abs(view.odom[-1].twist.twist.linear.x), 0.005, 'moving again')


class TestNan(unittest.TestCase):
    def test_non_finite_twist_rejected_previous_command_stays(self):
        view = RobotView('/env_0/')
        diagnostics = Diagnostics()
        limit = spec().action_high[0]
        v = 0.5 * limit * spec().wheel_radius
        view.drive(twist(v, 0.0), 1.5)
        # only NaN and Inf for 0.6 s (cmd_vel_timeout is 3 s): rejected, the robot drives on
        nan = twist(float('nan'), 0.0)
        inf = twist(0.0, float('inf'))
        m = Motion(view.drive(nan, 0.6, also=lambda: view.cmd.publish(inf)))
        print('after NaN and Inf twists: %s' % m)
        self.assertLess(abs(m.forward - v), 0.05 * v, m)
        status = diagnostics.wait(lambda d: int(d['rejected cmd_vel']) >= 2,
                                  what='the non-finite twists counted')
        self.assertIn('is not finite; the previous command stays',
                      status['last cmd_vel rejection reason'])
        self.assertTrue(any('nan' in d['last cmd_vel rejection reason'] or
                            'inf' in d['last cmd_vel rejection reason']
                            for d in diagnostics.statuses))
        # the previous command still expires with its own age: the robot brakes
        wait_for(lambda: abs(view.odom[-1].twist.twist.linear.x) < 0.005,
                 what='the robot to brake 3 s after the last valid cmd_vel')


CASES = {'drive': TestDrive, 'lockstep': TestLockstep, 'brake': TestBrake, 'nan': TestNan}

if __name__ == '__main__':
    rospy.init_node('test_cmd_vel')
    case = rospy.get_param('~case')
    rostest.rosrun('jetbot_rl', 'test_cmd_vel_' + case, CASES[case])
