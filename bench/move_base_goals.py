#!/usr/bin/python3
"""Goals anywhere reachable through the move_base action, as issue 33's targets measure the learnt
navigator: against a running navigate_sim.launch (or any navigator serving move_base with the
env node's robot view), draws --goals goals on the map's free cells (--clearance from its walls,
unknown cells counted as walls, at least --min-distance from where the robot is, a random
heading; seeded), sends each through actionlib's SimpleActionClient and waits for its end.
Prints a line per goal and the figures: SUCCEEDED share, goals with a touch (a scan reading below
range_min, which the env node reports as -inf), the time over the time of its plan at --speed
(the policy's top speed), and the recoveries the navigator's /diagnostics count.

    roslaunch jetbot_rl navigate_sim.launch checkpoint:=RUN_DIR
    rosrun jetbot_rl move_base_goals.py --goals 20 --seed 1
"""
import argparse
import math
import sys
import time

import numpy as np
import rospy
from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray
from move_base_msgs.msg import MoveBaseAction
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from sensor_msgs.msg import LaserScan

from jetbot_rl.action_client import SimpleActionClient, clock_hint, wait_for_server
from jetbot_rl.move_base_goal import move_base_goal


STATES = {v: k for k, v in vars(GoalStatus).items() if k.isupper() and isinstance(v, int)}


class Recorder(object):
    def __init__(self, args):
        self.map = None
        self.odom = None
        self.plans = []
        self.touched = False
        self.recoveries = None
        rospy.Subscriber(args.map, OccupancyGrid, self.on_map)
        rospy.Subscriber(args.odom, Odometry, self.on_odom)
        rospy.Subscriber(args.scan, LaserScan, self.on_scan)
        rospy.Subscriber(args.plan, Path, self.plans.append)
        rospy.Subscriber('/diagnostics', DiagnosticArray, self.on_diagnostics)

    def on_map(self, msg):
        self.map = msg

    def on_odom(self, msg):
        self.odom = msg

    def on_scan(self, msg):
        if any(r == float('-inf') for r in msg.ranges):
            self.touched = True

    def on_diagnostics(self, msg):
        for status in msg.status:
            for kv in status.values:
                if kv.key == 'recoveries' and status.name.endswith(': deploy'):
                    self.recoveries = int(kv.value)


def wait(condition, what, timeout=60.0):
    end = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > end or rospy.is_shutdown():
            raise RuntimeError('no %s after %.0f s' % (what, timeout))
        time.sleep(0.05)


def free_points(grid, clearance):
    """Centres of free cells at least `clearance` [m] from every cell that is not free (map frame,
    axis-aligned maps)."""
    info = grid.info
    cells = np.array(grid.data, dtype=np.int16).reshape(info.height, info.width)
    res = info.resolution
    ys, xs = np.nonzero(cells != 0)
    walls = np.stack([xs, ys], axis=1).astype(np.float64) * res
    fy, fx = np.nonzero(cells == 0)
    free = np.stack([fx, fy], axis=1).astype(np.float64) * res
    keep = np.ones(len(free), dtype=bool)
    for start in range(0, len(free), 2000):  # in chunks: walls x free cells
        chunk = free[start:start + 2000]
        d2 = ((chunk[:, None, :] - walls[None, :, :]) ** 2).sum(axis=2).min(axis=1)
        keep[start:start + 2000] = d2 >= clearance ** 2
    origin = np.array([info.origin.position.x, info.origin.position.y])
    return free[keep] + origin + 0.5 * res


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--goals', type=int, default=20)
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--clearance', type=float, default=0.35, help='from the map\'s walls [m]')
    parser.add_argument('--min-distance', type=float, default=1.0, help='from the robot [m]')
    parser.add_argument('--speed', type=float, default=0.6, help='the policy\'s top speed [m/s]')
    parser.add_argument('--timeout', type=float, default=150.0, help='per goal [s]')
    parser.add_argument('--frame', default='env_0/map', help='the map\'s frame (goals are in it)')
    parser.add_argument('--action', default='move_base')
    parser.add_argument('--map', default='/map')
    parser.add_argument('--odom', default='/env_0/odom')
    parser.add_argument('--scan', default='/env_0/scan')
    parser.add_argument('--plan', default='/navigate/plan')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('move_base_goals', anonymous=True)
    rec = Recorder(args)
    client = SimpleActionClient(args.action, MoveBaseAction)
    # In wall time, after the first /clock: actionlib's wait_for_server would compute its deadline
    # from the time 0 a node has before its first /clock under /use_sim_time.
    if not wait_for_server(client, 60.0):
        print('no action server %s after 60 s%s' % (rospy.resolve_name(args.action), clock_hint()),
              file=sys.stderr)
        return 1
    wait(lambda: rec.map is not None and rec.odom is not None, 'map and odometry')
    points = free_points(rec.map, args.clearance)
    rng = np.random.default_rng(args.seed)
    rows = []
    for k in range(args.goals):
        p = rec.odom.pose.pose.position  # the env's odom frame is its map frame (no drift)
        while True:
            x, y = points[rng.integers(len(points))]
            if math.hypot(x - p.x, y - p.y) >= args.min_distance:
                break
        heading = rng.uniform(-math.pi, math.pi)
        goal = move_base_goal(x, y, heading, args.frame)
        plans = len(rec.plans)
        rec.touched = False
        sent = time.monotonic()
        client.send_goal(goal)
        ended = client.wait_for_result(rospy.Duration(args.timeout))
        took = time.monotonic() - sent
        if not ended:
            # One goal at a time: a goal left running would be preempted by the next, its end
            # reported nowhere (the client tracks its newest goal only).
            client.cancel_goal()
            if not client.wait_for_result(rospy.Duration(10.0)):
                print('goal %d has not ended 10 s after its cancel' % (k + 1), file=sys.stderr)
                return 1
        state = client.get_state()
        plan = next((q for q in rec.plans[plans:] if q.poses), None)
        length = 0.0
        if plan is not None:
            xy = [(q.pose.position.x, q.pose.position.y) for q in plan.poses]
            length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(xy, xy[1:]))
        ratio = took / (length / args.speed) if length > 0 else float('nan')
        rows.append((state == GoalStatus.SUCCEEDED, rec.touched, ratio))
        print('goal %2d (%5.2f, %5.2f, %5.2f): %-9s in %5.1f s, plan %5.2f m (straight %4.2f), '
              'time / plan time %4.2f%s: %s'
              % (k + 1, x, y, heading, STATES.get(state, str(state)), took,
                 length, math.hypot(x - p.x, y - p.y), ratio, ', touched' if rec.touched else '',
                 client.get_goal_status_text()), flush=True)
    succeeded = [r for r in rows if r[0]]
    ratios = [r[2] for r in succeeded if not math.isnan(r[2])]
    print('FIGURE: move_base goals: %d of %d SUCCEEDED (%.0f %%), %d with a touch, time over the '
          'plan time at %.2f m/s: median %.2f, max %.2f, %d of %d within 2x; recoveries %s'
          % (len(succeeded), len(rows), 100.0 * len(succeeded) / len(rows),
             sum(1 for r in rows if r[1]), args.speed,
             float(np.median(ratios)) if ratios else float('nan'),
             max(ratios) if ratios else float('nan'), sum(1 for r in ratios if r <= 2.0),
             len(succeeded), rec.recoveries))
    return 0


if __name__ == '__main__':
    sys.exit(main())
