"""Test helpers for the robot view of jetbot_env: one env's cmd_vel, odom and joint_states, and
figures measured on odom over simulation time."""
import math
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

from jetbot_rl_test.env_client import TIMEOUT, ConnectionListener, EventList, wait_for

DRIVE_CADENCE = 0.1  # s between cmd_vel messages: a teleop's 10 Hz (pacing, not synchronisation)


def yaw(q):
    """Yaw [rad] of a geometry_msgs/Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def twist(linear, angular):
    msg = Twist()
    msg.linear.x = linear
    msg.angular.z = angular
    return msg


def stamp(msg):
    return msg.header.stamp.to_sec()


class Motion(object):
    """What odom says over a window of simulation time."""

    def __init__(self, odoms):
        assert len(odoms) >= 2, 'fewer than 2 odom messages in the window'
        self.seconds = stamp(odoms[-1]) - stamp(odoms[0])
        path = 0.0
        turned = 0.0
        for a, b in zip(odoms, odoms[1:]):
            pa, pb = a.pose.pose.position, b.pose.pose.position
            step = math.hypot(pb.x - pa.x, pb.y - pa.y)
            # a time-out resets the env to its start: no window may hold one (1 m/s at most)
            assert step < 1.0 * (stamp(b) - stamp(a)) + 1e-3, \
                'odom jumped %.3f m at %.3f s: the env was reset' % (step, stamp(b))
            path += step
            d = yaw(b.pose.pose.orientation) - yaw(a.pose.pose.orientation)
            turned += math.atan2(math.sin(d), math.cos(d))  # unwrapped
        first, last = odoms[0].pose.pose, odoms[-1].pose.pose
        heading = yaw(first.orientation)
        along = ((last.position.x - first.position.x) * math.cos(heading) +
                 (last.position.y - first.position.y) * math.sin(heading))
        self.speed = path / self.seconds                        # along the path [m/s]
        self.forward = along / self.seconds                     # along the first heading [m/s]
        self.yaw_rate = turned / self.seconds                   # [rad/s]
        n = float(len(odoms))
        self.twist_linear = sum(o.twist.twist.linear.x for o in odoms) / n   # mean, base frame
        self.twist_angular = sum(o.twist.twist.angular.z for o in odoms) / n

    def __repr__(self):
        return ('Motion(%.2f s: speed %.4f m/s, forward %.4f m/s, yaw rate %.4f rad/s; twist %.4f, '
                '%.4f)' % (self.seconds, self.speed, self.forward, self.yaw_rate,
                           self.twist_linear, self.twist_angular))


class RobotView(object):
    """One env's robot view: publishes on `<prefix>cmd_vel`, records `<prefix>odom` and
    `<prefix>joint_states` (prefix e.g. '/env_0/', or '/' for an unprefixed node)."""

    def __init__(self, prefix='/env_0/', wait_state=True):
        """`wait_state`: wait for the first odom and joint_states (realtime mode; a lockstep
        node publishes them only when it steps)."""
        self.prefix = prefix
        self.odom = EventList()
        self.joints = EventList()
        self.cmd = rospy.Publisher(prefix + 'cmd_vel', Twist, queue_size=10,
                                   subscriber_listener=ConnectionListener())
        self.odom_sub = rospy.Subscriber(prefix + 'odom', Odometry, self.odom.append,
                                         queue_size=1000, tcp_nodelay=True)
        self.joint_sub = rospy.Subscriber(prefix + 'joint_states', JointState, self.joints.append,
                                          queue_size=1000, tcp_nodelay=True)
        wait_for(lambda: self.cmd.get_num_connections() > 0,
                 what='the node to subscribe to %scmd_vel' % prefix)
        wait_for(lambda: self.odom_sub.get_num_connections() > 0 and
                 self.joint_sub.get_num_connections() > 0,
                 what='%sodom and %sjoint_states to connect' % (prefix, prefix), recheck=0.05)
        if wait_state:
            wait_for(lambda: len(self.odom) > 0 and len(self.joints) > 0,
                     what='%sodom and %sjoint_states' % (prefix, prefix))

    def now(self):
        """Simulation time of the newest odom [s]."""
        return stamp(self.odom[-1])

    def wait_sim(self, seconds, what='simulation time to pass'):
        """Waits until odom has advanced `seconds` of simulation time from now."""
        end = self.now() + seconds
        wait_for(lambda: self.now() >= end, what=what)

    def drive(self, msg, seconds, also=None):
        """Publishes `msg` (and calls `also()`) every DRIVE_CADENCE s of wall time until odom has
        advanced `seconds` of simulation time; returns the odom messages of that span."""
        start_count = len(self.odom)
        end = self.now() + seconds
        deadline = time.monotonic() + TIMEOUT + seconds
        while self.now() < end:
            self.cmd.publish(msg)
            if also:
                also()
            time.sleep(DRIVE_CADENCE)
            if time.monotonic() > deadline or rospy.is_shutdown():
                raise AssertionError('odom did not advance %.1f s while driving' % seconds)
        return list(self.odom[start_count:])

    def measure(self, msg, settle=1.5, seconds=1.0, also=None):
        """Drives `msg` for `settle` s, then returns the Motion over the next `seconds` s (of
        simulation time)."""
        self.drive(msg, settle, also)
        return Motion(self.drive(msg, seconds, also))


class Diagnostics(object):
    """Every jetbot_env status on /diagnostics, as a dict key -> value."""

    def __init__(self):
        self.statuses = EventList()
        self.sub = rospy.Subscriber('/diagnostics', DiagnosticArray, self._on_diag)

    def _on_diag(self, msg):
        self.statuses.extend({kv.key: kv.value for kv in s.values}
                             for s in msg.status if s.name.startswith('jetbot_env'))

    def find(self, predicate):
        """The first status received that satisfies `predicate`, or None."""
        return next((d for d in list(self.statuses) if predicate(d)), None)

    def wait(self, predicate, what):
        """Waits for a status satisfying `predicate`; returns it."""
        wait_for(lambda: self.find(predicate) is not None, what=what)
        return self.find(predicate)
