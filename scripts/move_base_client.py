#!/usr/bin/python3
"""Sends goals to the move_base action as a mission script would (actionlib's
SimpleActionClient, move_base_msgs/MoveBaseAction): the learnt navigator of navigate.launch or
navigate_sim.launch, or move_base itself. Each goal is x y [yaw] in --frame; the script waits for
each result, prints it with the time it took and the last feedback, and exits 1 when any goal
did not succeed.

    roslaunch jetbot_rl navigate_sim.launch checkpoint:=RUN_DIR
    rosrun jetbot_rl move_base_client.py 0.0 2.0 1.57  -3.0 0.0 0.0   # two goals, x y yaw
    rosrun jetbot_rl move_base_client.py --cancel-after 2 1.5 -0.5    # cancel it after 2 s
"""
import argparse
import sys

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction

from jetbot_rl.move_base_goal import move_base_goal

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
    parser.add_argument('--cancel-after', type=float, default=0.0,
                        help='cancel each goal after this many seconds (default 0: never)')
    args = parser.parse_args(rospy.myargv()[1:])
    try:
        goals = goals_of(args.values)
    except ValueError as e:
        parser.error(str(e))
    rospy.init_node('move_base_client', anonymous=True)
    client = actionlib.SimpleActionClient(args.action, MoveBaseAction)
    if not client.wait_for_server(rospy.Duration(30.0)):
        rospy.logfatal('no action server %s after 30 s', args.action)
        return 1
    failed = 0
    for x, y, yaw in goals:
        goal = move_base_goal(x, y, yaw, args.frame, stamp=rospy.Time.now())
        last = []
        start = rospy.get_time()
        client.send_goal(goal, feedback_cb=last.append)
        if args.cancel_after > 0.0:
            client.wait_for_result(rospy.Duration(args.cancel_after))
            if client.get_state() in (GoalStatus.PENDING, GoalStatus.ACTIVE):
                client.cancel_goal()
        client.wait_for_result(rospy.Duration(args.timeout))
        state = client.get_state()
        where = ''
        if last:
            p = last[-1].base_position
            where = ' at (%.2f, %.2f) in %s' % (p.pose.position.x, p.pose.position.y,
                                                 p.header.frame_id)
        print('goal (%.2f, %.2f, %.2f): %s after %.1f s%s: %s'
              % (x, y, yaw, STATES.get(state, state), rospy.get_time() - start, where,
                 client.get_goal_status_text()))
        failed += state != GoalStatus.SUCCEEDED
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
