"""Helpers of the fault suite: figures in the test output, processes started, signalled and
killed by the test, the resident set of a node, and /diagnostics windows."""
import os
import subprocess
import sys
import time

import rospkg
import rospy
from diagnostic_msgs.msg import DiagnosticArray

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for

PYTHON = '/usr/bin/python3'  # ROS's interpreter (the first python3 on the PATH may lack rospy)


def figure(text):
    """Prints a measured figure as `FIGURE: text` (rostest keeps the test's stdout)."""
    sys.stdout.write('FIGURE: %s\n' % text)
    sys.stdout.flush()


def package_file(*parts):
    """Path of a file of the jetbot_rl package (its source folder: the tests run from there),
    e.g. package_file('test', 'reliability', 'lockstep_client.py')."""
    return os.path.join(rospkg.RosPack().get_path('jetbot_rl'), *parts)


def node_command(node_type, name, params):
    """rosrun command line of a jetbot_rl node named `name` with private parameters `params`."""
    command = ['rosrun', 'jetbot_rl', node_type, '__name:=' + name]
    return command + ['_%s:=%s' % (k, v) for k, v in params.items()]


def start(command, log_path=None):
    """Starts `command` (rosrun execs the node: the same pid gets the signals) with its output
    in `log_path` (default: a pipe read by finish())."""
    out = open(log_path, 'w') if log_path else subprocess.PIPE
    return subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT,
                            universal_newlines=True)


def signal_and_wait(proc, sig, timeout=30.0):
    """Sends `sig` to `proc` and waits for its end: (seconds from the signal to the exit, exit
    status, output)."""
    started = time.monotonic()
    proc.send_signal(sig)
    output, _ = proc.communicate(timeout=timeout)
    return time.monotonic() - started, proc.returncode, output or ''


def stop_all(*procs):
    """Kills those of `procs` (None allowed) still running and reaps them: a failed test leaves
    no process behind."""
    for proc in procs:
        if proc and proc.poll() is None:
            proc.kill()
            proc.wait()


class DiagnosticsRecorder(object):
    """Records every /diagnostics status of env node `node` (e.g. /jetbot_env) as a dict of its
    values plus 'stamp' [s] (wall time: the node is the clock source)."""

    def __init__(self, node='/jetbot_env'):
        self.name = node.lstrip('/') + ': environment'
        self.reports = EventList()
        self.sub = rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diag)

    def _on_diag(self, msg):
        for status in msg.status:
            if status.name == self.name:
                values = {kv.key: kv.value for kv in status.values}
                values['stamp'] = msg.header.stamp.to_sec()
                self.reports.append(values)

    def next(self, predicate=lambda r: True, what='a /diagnostics report', timeout=TIMEOUT):
        """The first report from now on that satisfies `predicate`."""
        start = len(self.reports)
        found = []

        def check():
            for r in self.reports[start:]:
                if predicate(r):
                    found.append(r)
                    return True
            return False
        wait_for(check, timeout=timeout, what=what)
        return found[0]

    def rate(self, reports, on_report=None):
        """Steps per wall second over the next `reports` report intervals (steps applied between
        the first and the last report over their stamps' difference); `on_report(report)` is
        called for each report."""
        first = self.next()
        last = first
        for _ in range(reports):
            stamp = last['stamp']
            last = self.next(lambda r: r['stamp'] > stamp)
            if on_report:
                on_report(last)
        return rate_between(first, last)


def rate_between(first, last):
    """Steps per wall second from diagnostics report `first` to report `last`."""
    steps = int(last['steps applied']) - int(first['steps applied'])
    return steps / (last['stamp'] - first['stamp'])
