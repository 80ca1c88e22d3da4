#!/usr/bin/python3
"""Two learners answer every EnvStep with WheelTargets for the same step id, for 10,000 steps:
exactly one answer per step is applied and the other is rejected as stale and counted in
/diagnostics; the EnvStep ids published are 1..10000, none skipped and none twice. Prints the
counts and the step rate."""
import time
import unittest

import rospy
import rostest
from std_msgs.msg import Bool

from jetbot_rl.msg import EnvStep
from jetbot_rl.srv import Reset
from jetbot_rl_test.env_client import NODE, UNREPORTED_RECHECK, EventList, wait_for
from jetbot_rl_test.fault_util import DiagnosticsRecorder, figure

LEARNERS = ('/learner_a', '/learner_b')  # two_learners.test


class TestTwoLearners(unittest.TestCase):
    def test_each_step_applied_once(self):
        steps = rospy.get_param('~steps')
        ids = EventList()
        sub = rospy.Subscriber(NODE + '/env_step', EnvStep, lambda m: ids.append(m.step),
                               tcp_nodelay=True)
        ready = EventList()
        for learner in LEARNERS:
            rospy.Subscriber(learner + '/ready', Bool, lambda m, l=learner: ready.append(l))
        diagnostics = DiagnosticsRecorder(NODE)
        wait_for(lambda: set(ready) == set(LEARNERS), what='both learners to be connected')
        wait_for(lambda: sub.get_num_connections() > 0, what='our env_step subscription',
                 recheck=UNREPORTED_RECHECK)
        before = diagnostics.next()
        self.assertEqual(int(before['steps applied']), 0)

        rospy.wait_for_service(NODE + '/reset')
        started = time.monotonic()
        state = rospy.ServiceProxy(NODE + '/reset', Reset)(env_ids=[], seed=-1).state
        self.assertEqual(state.step, 0)  # its publication starts both learners
        wait_for(lambda: ids and ids[-1] >= steps, timeout=600.0,
                 what='EnvStep %d (got up to %s)' % (steps, ids[-1] if ids else None))
        seconds = time.monotonic() - started
        self.assertEqual(list(ids), list(range(0, steps + 1)), 'EnvStep ids skipped or doubled')
        report = diagnostics.next(lambda r: int(r['rejected messages']) >= steps,
                                  what='%d rejections on /diagnostics' % steps)
        later = diagnostics.next(lambda r: r['stamp'] > report['stamp'])  # none after them
        self.assertEqual(int(later['steps applied']), steps)
        self.assertEqual(int(later['current step']), steps)
        self.assertEqual(int(later['rejected messages']), steps)
        self.assertTrue(later['last rejection reason'].startswith(
            'wheel_targets rejected: stale step'), later['last rejection reason'])
        figure('two learners answering every step: %d steps applied, %d stale answers rejected '
               'and counted, EnvStep ids 1..%d each once, %.0f steps/s'
               % (int(later['steps applied']), int(later['rejected messages']), steps,
                  steps / seconds))


if __name__ == '__main__':
    rospy.init_node('test_two_learners')
    rostest.rosrun('jetbot_rl', 'test_two_learners', TestTwoLearners)
