"""Helpers of the Python client's rostests: node processes, diagnostics, waiting on events, a
spec's observation bounds."""
import os
import signal
import threading

import numpy as np
import rospy
from diagnostic_msgs.msg import DiagnosticArray

TIMEOUT = 30.0  # s: generous, for a loaded 2-core machine


def interrupt_main_after(seconds):
    """Sends SIGINT to this process's main thread after `seconds` (as Ctrl-C would)."""
    main = threading.main_thread().ident
    timer = threading.Timer(seconds, lambda: signal.pthread_kill(main, signal.SIGINT))
    timer.start()
    return timer


def stop(pid):
    os.kill(pid, signal.SIGSTOP)


def resume(pid):
    os.kill(pid, signal.SIGCONT)


class Diagnostics(object):
    """The newest /diagnostics status of the env nodes, as dict key -> value; wait() for one."""

    def __init__(self):
        self._cond = threading.Condition()
        self._statuses = []
        self._sub = rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diag)

    def _on_diag(self, msg):
        with self._cond:
            for status in msg.status:
                if status.name.startswith('jetbot_env'):
                    self._statuses.append({kv.key: kv.value for kv in status.values})
            self._cond.notify_all()

    def wait(self, predicate, what, timeout=TIMEOUT):
        """Waits for a status satisfying `predicate` (woken by each report); returns it."""
        with self._cond:
            found = []

            def check():
                found.extend(s for s in self._statuses if predicate(s))
                self._statuses = []
                return bool(found)
            if not self._cond.wait_for(check, timeout):
                raise AssertionError('timed out after %.0f s waiting for %s' % (timeout, what))
            return found[0]


class EventList(list):
    """A list a callback appends to; wait_for() waits, woken by each append, for a condition."""

    def __init__(self):
        super(EventList, self).__init__()
        self._cond = threading.Condition()

    def append(self, item):
        with self._cond:
            super(EventList, self).append(item)
            self._cond.notify_all()

    def wait_for(self, condition, what, timeout=TIMEOUT):
        with self._cond:
            if not self._cond.wait_for(condition, timeout):
                raise AssertionError('timed out after %.0f s waiting for %s' % (timeout, what))


def spec_bounds(spec):
    """(observation_low, observation_high) of an EnvSpec as float32 arrays of obs_dim entries: what
    the spec says, -inf/inf everywhere when it sends none (empty lists)."""
    if len(spec.observation_low) == 0:
        return (np.full(spec.obs_dim, -np.inf, dtype=np.float32),
                np.full(spec.obs_dim, np.inf, dtype=np.float32))
    return (np.array(spec.observation_low, dtype=np.float32),
            np.array(spec.observation_high, dtype=np.float32))
