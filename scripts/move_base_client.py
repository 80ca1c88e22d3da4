#!/usr/bin/python3
"""Sends goals to the move_base action as a mission script would (actionlib's
SimpleActionClient, move_base_msgs/MoveBaseAction): the learnt navigator of navigate.launch or
navigate_sim.launch, or move_base itself. Each goal is x y [yaw] in --frame; the script waits for
each result, prints it with the time it took and the last feedback, and exits 1 when any goal
did not succeed. One goal at a time: a goal without a result within --timeout is canceled, and
its end awaited, before the next is sent. The server is awaited for --server-timeout seconds of
wall time, also under /use_sim_time, and no status of a goal is dropped
(jetbot_rl.action_client: actionlib's own wait_for_server gives up at once when the node's first
/clock comes after the simulation's first 30 s, and its SimpleActionClient drops a status that
comes before send_goal returns, "[ERROR] Got a transition callback on a goal handle that we're
not tracking").

    roslaunch jetbot_rl navigate_sim.launch checkpoint:=RUN_DIR
    rosrun jetbot_rl move_base_client.py 0.0 2.0 1.57  -3.0 0.0 0.0   # two goals, x y yaw
    rosrun jetbot_rl move_base_client.py --cancel-after 2 1.5 -0.5    # cancel it after 2 s
"""
import argparse
import sys

import rospy
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction

from jetbot_rl.action_client import SimpleActionClient, clock_hint, wait_for_server
from jetbot_rl.move_base_goal import move_base_goal

CANCEL_WAIT = 10.0  # [s]: for a canceled goal's end before giving up
STATES = {v: k for k, v in vars(GoalStatus).items() if k.isupper() and isinstance(v, int)}


def goals_of(values):
    """x y yaw triples from a flat list; a single goal may leave out its yaw (0)."""
    if len(values) == 2:
        return [(values[0], values[1], 0.0)]
    if len(values) % 3:
        raise ValueError('%d values: give x y yaw for each goal' % len(values))
    return [tuple(values[i:i + 3]) for i in range(0, len(values), 3)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('values', nargs='+', type=float,
                        help='goals: x y yaw each (one goal may be x y: yaw 0)')
    parser.add_argument('--frame', default='env_0/map', help='the goals\' frame (default env_0/map)')
    parser.add_argument('--action', default='move_base', help='the action server (default move_base)')
    parser.add_argument('--timeout', type=float, default=180.0, help='per goal [s] (default 180)')
    parser.add_argument('--server-timeout', type=float, default=30.0,
                        help='wait this long for the action server [s, wall time] (default 30)')
    parser.add_argument('--cancel-after', type=float, default=0.0,
                        help='cancel each goal after this many seconds (default 0: never)')
    args = parser.parse_args(rospy.myargv()[1:])
    try:
        goals = goals_of(args.values)
    except ValueError as e:
        parser.error(str(e))
    rospy.init_node('move_base_client', anonymous=True)
    client = SimpleActionClient(args.action, MoveBaseAction)
    # In wall time, after the first /clock under /use_sim_time: actionlib's wait_for_server would
    # compute its deadline from the time 0 a node has before its first /clock.
    if not wait_for_server(client, args.server_timeout):
        rospy.logfatal('no action server %s after %.0f s%s', rospy.resolve_name(args.action),
                       args.server_timeout, clock_hint())
        return 1
    failed = 0
    # One goal at a time: each ends (its result received) before the next is sent. A goal left
    # running would be preempted by the next on the server, its end reported nowhere: the client
    # tracks its newest goal only.
    for x, y, yaw in goals:
        goal = move_base_goal(x, y, yaw, args.frame, stamp=rospy.Time.now())
        last = []
        start = rospy.get_time()
        client.send_goal(goal, feedback_cb=last.append)
        if args.cancel_after > 0.0 and not client.wait_for_result(
                rospy.Duration(args.cancel_after)):
            client.cancel_goal()
        note = ''
        if not client.wait_for_result(rospy.Duration(args.timeout)):
            client.cancel_goal()
            if rospy.is_shutdown():
                return 1
            note = ' (canceled: no result within %g s)' % args.timeout
            if not client.wait_for_result(rospy.Duration(CANCEL_WAIT)):
                rospy.logerr('goal (%.2f, %.2f, %.2f) has not ended %g s after its cancel: no '
                             'further goal sent', x, y, yaw, CANCEL_WAIT)
                return 1
        state = client.get_state()
        where = ''
        if last:
            p = last[-1].base_position
            where = ' at (%.2f, %.2f) in %s' % (p.pose.position.x, p.pose.position.y,
                                                 p.header.frame_id)
        print('goal (%.2f, %.2f, %.2f): %s after %.1f s%s: %s%s'
              % (x, y, yaw, STATES.get(state, state), rospy.get_time() - start, where,
                 client.get_goal_status_text(), note), flush=True)
        failed += state != GoalStatus.SUCCEEDED
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
