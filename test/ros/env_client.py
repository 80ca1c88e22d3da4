"""Test helpers: a lockstep client of jetbot_env (topics, services, diagnostics) for rostests."""
import threading
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray

from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.srv import Reset, Step

NODE = '/jetbot_env'
TIMEOUT = 30.0  # s: generous, for a loaded 2-core machine


def wait_for(condition, timeout=TIMEOUT, what='condition'):
    """Polls `condition` (cheaply, 5 ms) until it is true; fails with `what` after `timeout` s."""
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline or rospy.is_shutdown():
            raise AssertionError('timed out after %.0f s waiting for %s' % (timeout, what))
        time.sleep(0.005)


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
                                   tcp_nodelay=True)
        self.sub = rospy.Subscriber(NODE + '/env_step', EnvStep, self._on_step, tcp_nodelay=True,
                                    queue_size=1000)
        self.diag_sub = rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diag)
        wait_for(lambda: self.pub.get_num_connections() > 0, what='the node to subscribe')
        wait_for(lambda: self.sub.get_num_connections() > 0, what='env_step to connect')

    def _on_step(self, msg):
        with self.lock:
            self.steps.append(msg)

    def _on_diag(self, msg):
        for status in msg.status:
            if status.name.startswith('jetbot_env'):
                with self.lock:
                    self.diagnostics.append({kv.key: kv.value for kv in status.values})

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
