#!/usr/bin/python3
"""Two learners answer every EnvStep with WheelTargets for the same step id, for 10,000 steps:
exactly one answer per step is applied and every other answer the learners sent is rejected as
stale and counted in /diagnostics; the EnvStep ids published from the reset on are 0..10000, none
skipped and none twice (the node's start-up state, seen first when the test's subscription was
connected before the node published it, is left out). Prints the counts and the step rate.

A learner that falls behind (a loaded machine) may miss EnvSteps and answer fewer: the test counts
the answers each learner says it sent, not one per step."""
import time
import unittest

import rospy
import rostest
from std_msgs.msg import Bool, Int64

from jetbot_rl.msg import EnvStep
from jetbot_rl.srv import Reset
from jetbot_rl_test.env_client import NODE, UNREPORTED_RECHECK, EventList, notify, wait_for
from jetbot_rl_test.fault_util import DiagnosticsRecorder, figure

LEARNERS = ('/learner_a', '/learner_b')  # two_learners.test


class TestTwoLearners(unittest.TestCase):
    def test_each_step_applied_once(self):
        steps = rospy.get_param('~steps')
        ids = EventList()
        sub = rospy.Subscriber(NODE + '/env_step', EnvStep, lambda m: ids.append(m.step),
                               tcp_nodelay=True)
        ready = EventList()
        answered = {}  # learner: answers it has published so far
        for learner in LEARNERS:
            rospy.Subscriber(learner + '/ready', Bool, lambda m, l=learner: ready.append(l))
            rospy.Subscriber(learner + '/answered', Int64,
                             lambda m, l=learner: (answered.__setitem__(l, m.data), notify()))
        diagnostics = DiagnosticsRecorder(NODE)
        wait_for(lambda: set(ready) == set(LEARNERS), what='both learners to be connected')
        wait_for(lambda: sub.get_num_connections() > 0, what='our env_step subscription',
                 recheck=UNREPORTED_RECHECK)
        before = diagnostics.next()
        self.assertEqual(int(before['steps applied']), 0)
        # The node publishes its state once at start-up: our subscription sees it when it was
        # connected first (a slow start), and by now it has arrived (a diagnostics report later).
        start_up = len(ids)
        self.assertIn(list(ids), ([], [0]), 'EnvSteps before the reset: only the start-up state')

        rospy.wait_for_service(NODE + '/reset')
        started = time.monotonic()
        state = rospy.ServiceProxy(NODE + '/reset', Reset)(env_ids=[], seed=-1).state
        self.assertEqual(state.step, 0)  # its publication starts both learners
        wait_for(lambda: ids and ids[-1] >= steps, timeout=600.0,
                 what='EnvStep %d (got up to %s)' % (steps, ids[-1] if ids else None))
        seconds = time.monotonic() - started
        self.assertEqual(list(ids[start_up:]), list(range(0, steps + 1)),
                         'EnvStep ids skipped or doubled')

        def stale_answers():
            return sum(answered.get(l, 0) for l in LEARNERS) - steps

        # Each answer the node received is applied or counted: a lost one keeps this false.
        report = diagnostics.next(lambda r: int(r['rejected messages']) == stale_answers(),
                                  what='every stale answer counted on /diagnostics (%s)'
                                  % answered)
        self.assertGreater(int(report['rejected messages']), 0)
        self.assertEqual(int(report['steps applied']), steps)
        self.assertEqual(int(report['current step']), steps)
        self.assertTrue(report['last rejection reason'].startswith(
            'wheel_targets rejected: stale step'), report['last rejection reason'])
        figure('two learners answering every step: %d steps applied, %d stale answers rejected '
               'and counted (answers sent: %s), EnvStep ids 1..%d each once, %.0f steps/s'
               % (int(report['steps applied']), int(report['rejected messages']),
                  ', '.join('%s %d' % (l, answered[l]) for l in LEARNERS), steps,
                  steps / seconds))


if __name__ == '__main__':
    rospy.init_node('test_two_learners')
    rostest.rosrun('jetbot_rl', 'test_two_learners', TestTwoLearners)
