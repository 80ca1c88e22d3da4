#!/usr/bin/python3
"""Back-to-back ~step and ~reset calls beside a busy loop, with a subscriber of ~env_step that
keeps up and two that stall (256 envs: 10 kB per EnvStep, so that their queues overflow) (raw TCPROS connections that read nothing until the end): every
message a subscriber misses is one the node counts (/diagnostics "undelivered by topic") and
warns of (issue 49: roscpp dropped them from its queues without a count). Each subscriber's
misses are the gaps in the header.seq numbers it got, from its first message to the last one
published; the stalled ones read everything at the end."""
import re
import threading
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Log

from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.srv import Reset, Step
from jetbot_rl_test.env_client import NODE, TIMEOUT, UNREPORTED_RECHECK, notify, wait_for
from jetbot_rl_test.fault_util import DiagnosticsRecorder, figure
from jetbot_rl_test.raw_tcpros import StalledSubscriber

TOPIC = NODE + '/env_step'
STEPS = 1000  # back-to-back ~step calls
RESETS = 250  # then back-to-back ~reset calls
MIXED = 250  # then a ~reset after every ~step
STALLED = 2


def undelivered(report, topic):
    """The count of `topic` in a report's "undelivered by topic" ("topic: n, ..."), 0 if absent."""
    found = re.search(re.escape(topic) + r': (\d+)', report.get('undelivered by topic', ''))
    return int(found.group(1)) if found else 0


class TestCountedLosses(unittest.TestCase):
    def test_every_missed_message_is_counted(self):
        diagnostics = DiagnosticsRecorder(NODE)
        lock = threading.Lock()
        got = []  # (step, header.seq) of every EnvStep the subscriber that keeps up received
        warnings = []

        def on_step(msg):
            with lock:
                got.append((msg.step, msg.header.seq))
            notify()

        def on_log(msg):
            if msg.level == Log.WARN and 'not delivered' in msg.msg:
                with lock:
                    warnings.append(msg.msg)

        spec = rospy.wait_for_message(NODE + '/spec', EnvSpec, TIMEOUT)
        rospy.wait_for_service(NODE + '/step', TIMEOUT)
        step_srv = rospy.ServiceProxy(NODE + '/step', Step, persistent=True)
        reset_srv = rospy.ServiceProxy(NODE + '/reset', Reset, persistent=True)
        log_sub = rospy.Subscriber('/rosout', Log, on_log, queue_size=None)
        sub = rospy.Subscriber(TOPIC, EnvStep, on_step, queue_size=None, tcp_nodelay=True)
        stalled = [StalledSubscriber(TOPIC, EnvStep, NODE, caller_id='/stalled_%d' % k,
                                     rcvbuf=4096) for k in range(STALLED)]
        try:
            wait_for(lambda: sub.get_num_connections() > 0, what='our subscriber to connect',
                     recheck=UNREPORTED_RECHECK)
            # the node's connection header reached them: it queues every state from now on
            wait_for(lambda: all(s.unread_bytes() > 0 for s in stalled),
                     what='the stalled subscribers to connect', recheck=UNREPORTED_RECHECK)
            velocities = [1.0] * (spec.num_envs * spec.action_dim)

            def step(current):
                res = step_srv(WheelTargets(step=current, velocities=velocities))
                self.assertTrue(res.success, res.message)
                return res.state.step

            current = step_srv(WheelTargets(step=2 ** 64 - 1)).state.step  # refused: the state
            for _ in range(STEPS):
                current = step(current)
            for _ in range(RESETS):
                self.assertTrue(reset_srv().success)
            for _ in range(MIXED):
                current = step(current)
                self.assertTrue(reset_srv().success)
            current = step(current)  # the last state: the only one with this step
            wait_for(lambda: got and got[-1][0] == current, what='the last state')
            last_seq = got[-1][1]
            received = {'/test_counted_losses': [seq for _, seq in got]}
            for k, s in enumerate(stalled):
                received['/stalled_%d' % k] = s.read_seqs(last_seq, TIMEOUT)
        finally:
            for s in stalled:
                s.close()
            sub.unregister()
        missed = {}
        for name, seqs in received.items():
            self.assertEqual(seqs, sorted(set(seqs)), '%s got states twice or out of order' % name)
            missed[name] = last_seq - seqs[0] + 1 - len(seqs)
        firsts = set(seqs[0] for seqs in received.values())
        self.assertEqual(len(firsts), 1, 'the subscribers began at different states: %s' % firsts)
        # the node counts at publication: the next report holds every drop
        report = diagnostics.next()
        report = diagnostics.next(lambda r: r['stamp'] > report['stamp'], what='the next report')
        counted = undelivered(report, TOPIC)
        published = last_seq - firsts.pop() + 1
        figure('%d states published back to back (%d ~step, %d ~reset, %d of each in turn) beside '
               'a busy loop: missed %s; the node counted %d undelivered on %s'
               % (published, STEPS + MIXED + 1, RESETS, MIXED,
                  ', '.join('%s %d' % kv for kv in sorted(missed.items())), counted, TOPIC))
        self.assertGreater(sum(missed.values()), 0, 'the stalled subscribers missed nothing')
        self.assertEqual(counted, sum(missed.values()), 'losses the node did not count')
        with lock:
            self.assertTrue(any(TOPIC in w for w in warnings), 'no WARN of the losses')
        log_sub.unregister()


if __name__ == '__main__':
    rospy.init_node('test_counted_losses')
    rostest.rosrun('jetbot_rl', 'test_counted_losses', TestCountedLosses)
