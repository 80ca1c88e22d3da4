#!/usr/bin/python3
"""Stalled subscribers of ~env_step (raw TCPROS connections that never read) neither slow
realtime stepping (the step rate stays within 5 % of the rate without them) nor grow the node's
memory (its resident set stays flat once their buffers are full: the node keeps at most its
queue per connection, 1 MiB of EnvSteps, reported on /diagnostics, and counts what it drops). 1000 envs: 40 kB per EnvStep. Prints both rates and the resident set."""
import io
import unittest

import rospy
import rostest

from jetbot_rl.msg import EnvStep
from jetbot_rl.process_info import node_pid, rss_kb
from jetbot_rl_test.env_client import NODE, UNREPORTED_RECHECK, wait_for
from jetbot_rl_test.fault_util import DiagnosticsRecorder, figure, rate_between
from jetbot_rl_test.raw_tcpros import StalledSubscriber

STALLED = 4
WINDOW = 10  # diagnostics reports (every 0.5 s: slow_subscriber.test) per measured window
FILL = 3  # reports after the kernel send queues and roscpp's queues are full, before measuring
MAX_RATE_CHANGE = 0.05
MAX_FLAT_KB = 2048  # resident set change over the measured window


class TestSlowSubscriber(unittest.TestCase):
    def test_stalled_subscribers_slow_nothing(self):
        pid = node_pid(NODE)
        diagnostics = DiagnosticsRecorder(NODE)
        sample = rospy.wait_for_message(NODE + '/env_step', EnvStep, 30.0)
        buff = io.BytesIO()
        sample.serialize(buff)
        msg_kb = len(buff.getvalue()) / 1024.0
        nominal = 1.0 / rospy.get_param(NODE + '/physics_dt') / \
            rospy.get_param(NODE + '/decimation') * rospy.get_param(NODE + '/real_time_factor')

        free_rate = diagnostics.rate(WINDOW)
        queue = int(diagnostics.reports[-1]['env_step queue'])  # EnvSteps per connection
        self.assertLessEqual(queue * msg_kb, max(1024.0, 16 * msg_kb) + msg_kb)  # 1 MiB, >= 16
        self.assertGreaterEqual(queue, 16)
        rss_free = rss_kb(pid)
        stalled = [StalledSubscriber(NODE + '/env_step', EnvStep, NODE,
                                     caller_id='/stalled_%d' % k, rcvbuf=4096)
                   for k in range(STALLED)]
        try:
            wait_for(lambda: all(s.unread_bytes() > 0 for s in stalled),
                     what='the node to write to the stalled subscribers',
                     recheck=UNREPORTED_RECHECK)  # our socket reports nothing
            # The node's kernel send queues fill first (megabytes: not its memory), then
            # roscpp's queue of each connection: wait until the send queues stop growing from
            # one report to the next, then FILL reports more.
            fill = [rss_kb(pid)]
            connected = diagnostics.next()
            queues = None
            for _ in range(60):
                diagnostics.next()
                fill.append(rss_kb(pid))
                previous, queues = queues, [s.unsent_bytes() for s in stalled]
                if queues == previous:
                    break
            self.assertEqual(queues, previous, 'the send queues never stopped growing')
            # roscpp's queues take `queue` steps more (every report: steps_per_report)
            steps_per_report = free_rate * rospy.get_param(NODE + "/diagnostic_period")
            fill_reports = FILL + int(queue / steps_per_report + 1.0)
            diagnostics.rate(fill_reports, lambda r: fill.append(rss_kb(pid)))
            rss = [rss_kb(pid)]
            stalled_rate = diagnostics.rate(WINDOW, lambda r: rss.append(rss_kb(pid)))
            unread = [s.unread_bytes() for s in stalled]
            filling_rate = rate_between(connected, diagnostics.reports[-1])
        finally:
            for s in stalled:
                s.close()
        change = stalled_rate / free_rate - 1.0
        figure('realtime stepping of %d envs (%.1f kB per EnvStep, nominal %.2f steps/s): '
               '%.2f steps/s without, %.2f steps/s with %d stalled subscribers (%+.1f %%; '
               '%.2f steps/s from their connection on, their queues filling included)'
               % (sample.num_envs, msg_kb, nominal, free_rate, stalled_rate, STALLED,
                  change * 100, filling_rate))
        figure('resident set: %d kB without; with %d stalled subscribers %d..%d kB while the '
               'send queues (%d kB each, in the kernel) and roscpp\'s queues filled, %d..%d kB '
               'over the next %d reports (change %+d kB); %d queued EnvSteps per connection '
               'are at most %.0f kB'
               % (rss_free, STALLED, min(fill), max(fill), queues[0] // 1024, min(rss),
                  max(rss), WINDOW, rss[-1] - rss[0], queue, queue * msg_kb))
        self.assertLess(abs(change), MAX_RATE_CHANGE)
        self.assertLess(abs(filling_rate / free_rate - 1.0), MAX_RATE_CHANGE)
        self.assertGreater(free_rate, nominal * (1.0 - MAX_RATE_CHANGE))
        self.assertTrue(all(u > 0 for u in unread), 'a stalled subscriber got nothing')
        self.assertLess(max(rss) - min(rss), MAX_FLAT_KB)
        # roscpp queues the same serialised messages for every connection: at most `queue` each
        self.assertLess(max(rss) - rss_free, STALLED * (queue + 1) * msg_kb + MAX_FLAT_KB)


if __name__ == '__main__':
    rospy.init_node('test_slow_subscriber')
    rostest.rosrun('jetbot_rl', 'test_slow_subscriber', TestSlowSubscriber)
