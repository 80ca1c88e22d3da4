"""Test helpers: a lockstep client of jetbot_env (topics, services, diagnostics) for rostests."""
import threading
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray

from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.srv import Reset, Step

NODE = '/jetbot_env'
TIMEOUT = 30.0  # s: generous, for a loaded 2-core machine


# Every callback of a test process notifies this after recording what it received, so that
# wait_for() wakes on the event instead of sleeping between checks.
_events = threading.Condition()
UNREPORTED_RECHECK = 0.05  # s: for what nothing reports (our subscribers connecting, the master)


def notify():
    """Wakes every wait_for(): call after recording anything a condition may look at."""
    with _events:
        _events.notify_all()


rospy.on_shutdown(notify)


def wait_for(condition, timeout=TIMEOUT, what='condition', recheck=None):
    """Waits until `condition()` holds, woken by notify(); fails naming `what` after `timeout` s.
    `recheck` [s] also re-evaluates it periodically: only for state no callback reports (our
    subscribers' connections, the master's registrations)."""
    deadline = time.monotonic() + timeout
    with _events:
        while not condition():
            remaining = deadline - time.monotonic()
            if remaining <= 0 or rospy.is_shutdown():
                raise AssertionError('timed out after %.0f s waiting for %s' % (timeout, what))
            _events.wait(remaining if recheck is None else min(remaining, recheck))


class EventList(list):
    """A list whose append and extend wake wait_for(): the record a test's own callback keeps."""

    def append(self, item):
        super(EventList, self).append(item)
        notify()

    def extend(self, items):
        super(EventList, self).extend(items)
        notify()


class ConnectionListener(rospy.SubscribeListener):
    """Wakes wait_for() when a subscriber connects to a publisher of ours."""

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        notify()


class EnvClient(object):
    """Records every EnvStep and /diagnostics status of the node; sends targets and calls."""

    def __init__(self):
        self.lock = threading.Lock()
        self.steps = []        # every EnvStep received, in order
        self.diagnostics = []  # dict key -> value of each jetbot_env status received
        rospy.wait_for_service(NODE + '/step', TIMEOUT)
        rospy.wait_for_service(NODE + '/reset', TIMEOUT)
        self.step_srv = rospy.ServiceProxy(NODE + '/step', Step, persistent=True)
        self.reset_srv = rospy.ServiceProxy(NODE + '/reset', Reset)
        self.spec = rospy.wait_for_message(NODE + '/spec', EnvSpec, TIMEOUT)
        self.pub = rospy.Publisher(NODE + '/wheel_targets', WheelTargets, queue_size=100,
                                   tcp_nodelay=True, subscriber_listener=ConnectionListener())
        self.sub = rospy.Subscriber(NODE + '/env_step', EnvStep, self._on_step, tcp_nodelay=True,
                                    queue_size=1000)
        self.diag_sub = rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diag)
        wait_for(lambda: self.pub.get_num_connections() > 0, what='the node to subscribe')
        wait_for(lambda: self.sub.get_num_connections() > 0, what='env_step to connect',
                 recheck=UNREPORTED_RECHECK)

    def _on_step(self, msg):
        with self.lock:
            self.steps.append(msg)
        notify()

    def _on_diag(self, msg):
        for status in msg.status:
            if status.name.startswith('jetbot_env'):
                with self.lock:
                    self.diagnostics.append({kv.key: kv.value for kv in status.values})
        notify()

    def received(self):
        with self.lock:
            return list(self.steps)

    def last(self):
        with self.lock:
            return self.steps[-1] if self.steps else None

    def targets(self, step, velocities):
        msg = WheelTargets()
        msg.header.stamp = rospy.Time.now()
        msg.step = step
        msg.velocities = list(velocities)
        return msg

    def publish(self, step, velocities):
        self.pub.publish(self.targets(step, velocities))

    def step_topic(self, step, velocities):
        """Publishes targets for `step` and returns the EnvStep with step + 1 (a reset's state
        published just before may still be on its way: messages up to `step` are skipped)."""
        count = len(self.received())
        self.publish(step, velocities)

        def answered():
            return any(m.step > step for m in self.received()[count:])
        wait_for(answered, what='EnvStep %d' % (step + 1))
        msg = next(m for m in self.received()[count:] if m.step > step)
        assert msg.step == step + 1, 'expected EnvStep %d, got %d' % (step + 1, msg.step)
        return msg

    def step_service(self, step, velocities):
        return self.step_srv(self.targets(step, velocities))

    def current(self):
        """The current state, without changing it: a stale ~step call is answered with it."""
        res = self.step_srv(self.targets(2 ** 64 - 1, []))
        assert not res.success
        return res.state

    def wait_diagnostics(self, predicate, what):
        """Waits for a jetbot_env diagnostics status satisfying `predicate`; returns it."""
        found = []

        def check():
            with self.lock:
                for status in self.diagnostics:
                    if predicate(status):
                        found.append(status)
                        return True
                self.diagnostics = []
                return False
        wait_for(check, what=what)
        return found[0]
