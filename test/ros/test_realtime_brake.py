#!/usr/bin/python3
"""Realtime mode: the node steps on its own with the latest targets (step field ignored), keeps
them between messages, and brakes to zero once they are older than action_timeout (0.5 s)."""
import time
import unittest

import rospy
import rostest

from diagnostic_msgs.msg import DiagnosticArray

from jetbot_rl.msg import EnvStep, WheelTargets
from jetbot_rl.srv import Step
from jetbot_rl_test.env_client import NODE, TIMEOUT, ConnectionListener, EventList, wait_for


class TestRealtimeBrake(unittest.TestCase):
    def test_drive_then_brake(self):
        steps = EventList()
        sub = rospy.Subscriber(NODE + '/env_step', EnvStep, steps.append, tcp_nodelay=True)
        pub = rospy.Publisher(NODE + '/wheel_targets', WheelTargets, queue_size=10,
                              tcp_nodelay=True, subscriber_listener=ConnectionListener())
        wait_for(lambda: pub.get_num_connections() > 0, what='the node to subscribe')
        wait_for(lambda: len(steps) >= 10, what='realtime steps without any targets')
        # at rest (the core's contact model lets a parked Jetbot creep at ~1 mm/s)
        self.assertLess(steps[-1].rewards[0], 0.01, 'moving before any targets')
        first = steps[-1].step

        # drive at 10 Hz (messages 0.1 s apart, well inside the 0.5 s time-out) for 2 s
        msg = WheelTargets(step=123456, velocities=[15.0, 15.0])  # step is ignored
        start = time.monotonic()
        while time.monotonic() - start < 2.0:
            pub.publish(msg)
            time.sleep(0.1)  # the driving cadence, not a synchronisation
        last_sent = len(steps)
        stop_step = steps[-1].step
        self.assertGreater(stop_step, first + 60, 'the node did not step on its own')
        driving = [m for m in steps if m.step > first]
        cruise = max(m.rewards[0] for m in driving)
        self.assertGreater(cruise, 0.1, 'targets were not applied')
        # after the first second the speed never dropped between messages
        settled = [m.rewards[0] for m in driving if m.step > first + 60 and m.step <= stop_step]
        self.assertTrue(settled)
        self.assertGreater(min(settled), 0.5 * cruise, 'braked while targets were fresh')
        # the steps right after the last message still use its targets ...
        wait_for(lambda: len(steps) >= last_sent + 5, what='steps after the last targets')
        after = [m.rewards[0] for m in steps[last_sent:last_sent + 5]]
        self.assertGreater(min(after), 0.5 * cruise, 'braked before action_timeout')
        # ... and once they are older than action_timeout the robot brakes to a stop
        wait_for(lambda: steps[-1].rewards[0] < 0.01, timeout=TIMEOUT,
                 what='the robot to brake after action_timeout')

        # an invalid message is rejected (counted in diagnostics) and stepping goes on
        status = EventList()
        diag = rospy.Subscriber('/diagnostics', DiagnosticArray, lambda m: status.extend(
            {kv.key: kv.value for kv in s.values} for s in m.status if s.name.startswith('jetbot')))
        pub.publish(WheelTargets(velocities=[1.0, 2.0, 3.0]))
        pub.publish(WheelTargets(velocities=[float('nan'), 2.0]))
        wait_for(lambda: any(int(d['rejected messages']) >= 1 for d in status),
                 what='a rejection counted in diagnostics')
        before = len(steps)
        wait_for(lambda: len(steps) > before + 10, what='steps after a rejection')
        self.assertLess(steps[-1].rewards[0], 0.01, 'an invalid message moved the robot')
        diag.unregister()

        # ~step is for lockstep mode only
        rospy.wait_for_service(NODE + '/step', TIMEOUT)
        res = rospy.ServiceProxy(NODE + '/step', Step)(actions=msg)
        self.assertFalse(res.success)
        self.assertIn('lockstep', res.message)
        sub.unregister()


if __name__ == '__main__':
    rospy.init_node('test_realtime_brake')
    rostest.rosrun('jetbot_rl', 'test_realtime_brake', TestRealtimeBrake)
