#!/usr/bin/python3
"""/clock is simulation time: step x control step, advancing by exactly one control step per
step (to the nanosecond), unchanged by resets, and equal to the EnvStep stamps."""
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock

from jetbot_rl_test.env_client import UNREPORTED_RECHECK, EnvClient, EventList, wait_for

STEPS = 40


class TestClock(unittest.TestCase):
    def test_clock_follows_steps(self):
        clocks = EventList()
        sub = rospy.Subscriber('/clock', Clock, lambda msg: clocks.append(msg.clock.to_nsec()),
                               tcp_nodelay=True)
        env = EnvClient()
        wait_for(lambda: sub.get_num_connections() > 0, what='/clock to connect',
                 recheck=UNREPORTED_RECHECK)
        dt_ns = env.spec.control_dt * 1e9

        def expected(step):
            return int(round(step * env.spec.control_dt * 1e9))
        state = env.reset_srv(env_ids=[], seed=-1).state
        wait_for(lambda: clocks and clocks[-1] == expected(state.step),
                 what='the clock of the reset state')
        self.assertEqual(state.header.stamp.to_nsec(), expected(state.step))
        seen = []
        for _ in range(STEPS):
            res = env.step_service(state.step, [3.0, 3.0, 1.0, 2.0])
            self.assertTrue(res.success, res.message)
            state = res.state
            wait_for(lambda: clocks and clocks[-1] == expected(state.step),
                     what='/clock of step %d' % state.step)
            self.assertEqual(state.header.stamp.to_nsec(), clocks[-1])
            seen.append(clocks[-1])
        for a, b in zip(seen, seen[1:]):
            self.assertLessEqual(abs((b - a) - dt_ns), 1.0)  # exactly one control step [ns]
        self.assertLessEqual(abs(seen[-1] - seen[0] - (STEPS - 1) * dt_ns), 1.0)
        # a reset does not advance time
        res = env.reset_srv(env_ids=[0], seed=-1)
        self.assertEqual(res.state.header.stamp.to_nsec(), seen[-1])


if __name__ == '__main__':
    rospy.init_node('test_clock')
    rostest.rosrun('jetbot_rl', 'test_clock', TestClock)
