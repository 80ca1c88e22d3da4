"""actionlib's SimpleActionClient as a mission script should use it, also under /use_sim_time:

    from jetbot_rl.action_client import SimpleActionClient, wait_for_server
    client = SimpleActionClient('move_base', MoveBaseAction)
    if not wait_for_server(client, 30.0):   # 30 s of wall time
        ...
    client.send_goal(goal)
    client.wait_for_result(rospy.Duration(60.0))

Two faults of actionlib (python3-actionlib 1.14) that a script meets (issue 50):

- `wait_for_server(timeout)` computes its deadline from rospy's time when it is called. Under
  /use_sim_time that time is 0 until the node has received its first /clock, some tens of
  milliseconds after rospy.init_node(): a deadline of 30 s computed from 0 has passed as soon as
  that clock arrives once the simulation has run for more than 30 s, and wait_for_server returns
  False at once, the server unseen (11 runs of 15 ended after 1.3 s with "no action server").
  Every deadline computed before the first /clock (`wait_for_result(timeout)` too) has the same
  fault. `wait_for_server()` below waits in wall time, after the first /clock.
- `SimpleActionClient.send_goal` stores the new goal's handle only when actionlib's
  `send_goal` has returned; a status of the goal (ACTIVE, or its end) that comes before that is
  dropped with `[ERROR] Got a transition callback on a goal handle that we're not tracking`
  (ros/actionlib issue 206, unfixed: ROS 1 is end-of-life), and a dropped end leaves
  `wait_for_result` waiting for its timeout. `SimpleActionClient` below holds such a callback
  until the handle is stored.
"""
import threading
import time

import actionlib
import rospy


class SimpleActionClient(actionlib.SimpleActionClient):
    """actionlib.SimpleActionClient whose goal callbacks (a transition, feedback) wait until
    send_goal has stored the new goal's handle, so that none of the new goal is dropped as
    "not tracking"."""

    def __init__(self, ns, ActionSpec):
        self._sending = threading.RLock()
        super(SimpleActionClient, self).__init__(ns, ActionSpec)

    def send_goal(self, goal, done_cb=None, active_cb=None, feedback_cb=None):
        with self._sending:
            super(SimpleActionClient, self).send_goal(goal, done_cb, active_cb, feedback_cb)

    def _handle_transition(self, gh):
        with self._sending:
            super(SimpleActionClient, self)._handle_transition(gh)

    def _handle_feedback(self, gh, feedback):
        with self._sending:
            super(SimpleActionClient, self)._handle_feedback(gh, feedback)


def wait_for_clock(timeout):
    """True once rospy's time is set: at once without /use_sim_time, else when the first /clock
    has come. Waits up to `timeout` seconds of wall time; False when none came (or on
    shutdown)."""
    deadline = time.monotonic() + timeout
    while rospy.get_rostime().is_zero():
        if rospy.is_shutdown() or time.monotonic() >= deadline:
            return False
        time.sleep(0.01)
    return True


def wait_for_server(client, timeout):
    """Waits up to `timeout` seconds of wall time for the action server of `client` (actionlib's
    SimpleActionClient or ActionClient, or the one above); True when it is there. Under
    /use_sim_time it waits for the first /clock first, then asks actionlib's own test in slices
    of 0.05 s of ROS time (the clock must run, as it does while a simulation serves the
    action)."""
    deadline = time.monotonic() + timeout
    if not wait_for_clock(timeout):
        return False
    while not rospy.is_shutdown():
        if client.wait_for_server(rospy.Duration(0.05)):
            return True
        if time.monotonic() >= deadline:
            return False
    return False


def clock_hint():
    """For an error message: ' (/use_sim_time is set and no /clock came: ...)' when that is why
    nothing was found, else ''."""
    if rospy.get_param('/use_sim_time', False) and rospy.get_rostime().is_zero():
        return ' (/use_sim_time is set and no /clock came: is the simulation running?)'
    return ''
