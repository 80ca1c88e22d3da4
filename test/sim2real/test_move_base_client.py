#!/usr/bin/python3
"""The example mission script as a user runs it (issue 50): `rosrun jetbot_rl move_base_client.py`
against navigate_sim.launch as the README starts it (no checkpoint: the shipped navigator), under
/use_sim_time, every run started after more than 30 s of simulated time. actionlib's own wait_for_server(30 s) computes its deadline from the
time 0 a node has before its first /clock, and gave up at once when that clock came after the
call but before the server's status (11 runs of 15 for the issue's user, `no action server
move_base after 30 s`; on this loaded 2-core machine 1 run of about 30). Each run must find the
server, send its goals one at a time, print each one's end, and print no error line (`[ERROR]
Got a transition callback on a goal handle that we're not tracking`: actionlib's
SimpleActionClient drops a status of a goal that comes before send_goal returns, here in 1 or 2
of 15 runs). A goal without a result within --timeout is canceled before the next (it was
left ACTIVE). The goals are ones the deploy node ends by itself (at the robot's place, turned to a
heading; refused) or the script cancels (--cancel-after, --timeout)."""
import re
import subprocess
import time
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatusArray
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock

from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for

SIM_TIME_BEFORE = 30.0    # [s] of simulated time before a client starts: the deadline it missed
TABLE = (2.25, -2.0)      # in the office's table
NEAR_WALL = (-0.87, 2.0)  # a free cell 3 cm from a wall: within the footprint
OTHER_SIDE = (-3.0, 0.0)  # behind the wall at x = -1
ERROR_LINE = re.compile(r'\[(ERROR|FATAL)\]|not tracking|Traceback')


def args_of(*goals):
    return [str(v) for goal in goals for v in goal]


class TestMoveBaseClient(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_move_base_client')
        cls.clocks, cls.odoms, cls.statuses = EventList(), EventList(), EventList()
        rospy.Subscriber('/clock', Clock, cls.clocks.append)
        rospy.Subscriber('/env_0/odom', Odometry, cls.odoms.append)
        rospy.Subscriber('/move_base/status', GoalStatusArray, cls.statuses.append)
        wait_for(lambda: cls.statuses, what='the move_base action server\'s status')

    def sim_time(self):
        return self.clocks[-1].clock.to_sec() if self.clocks else 0.0

    def client(self, *args):
        """Runs the script after SIM_TIME_BEFORE s of simulated time; returns its exit status and
        its lines (stdout and stderr), having checked that it found the server and printed no
        error."""
        wait_for(lambda: self.sim_time() > SIM_TIME_BEFORE, what='%.0f s of simulated time'
                 % SIM_TIME_BEFORE)
        started, sim_started = time.monotonic(), self.sim_time()
        run = subprocess.run(['rosrun', 'jetbot_rl', 'move_base_client.py'] + list(args),
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True, timeout=4 * TIMEOUT)
        print('FIGURE: move_base_client.py %s: exit %d after %.1f s (started at %.1f s of '
              'simulated time):\n%s' % (' '.join(args), run.returncode,
                                        time.monotonic() - started, sim_started, run.stdout))
        self.assertNotIn('no action server', run.stdout)
        self.assertEqual([line for line in run.stdout.splitlines() if ERROR_LINE.search(line)],
                         [])
        return run.returncode, [line for line in run.stdout.splitlines() if line.startswith('goal')]

    def test_0_every_run_finds_the_server(self):
        for run in range(4):
            rc, lines = self.client(*args_of(TABLE + (0.0,)))
            self.assertEqual(len(lines), 1, lines)
            self.assertIn(': ABORTED after', lines[0])
            self.assertEqual(rc, 1)

    def test_1_goals_one_after_the_other_find_the_server_and_succeed(self):
        wait_for(lambda: self.odoms, what='odometry')
        p = self.odoms[-1].pose.pose.position
        here = (round(p.x, 2), round(p.y, 2))
        for run in range(2):
            rc, lines = self.client(*args_of(here + (1.57,), here + (0.0,), here + (-1.57,),
                                             here + (0.0,)))
            self.assertEqual(len(lines), 4, lines)
            for line in lines:
                self.assertIn(': SUCCEEDED after', line)
            self.assertEqual(rc, 0)

    def test_2_refused_goals_abort_at_once(self):
        rc, lines = self.client(*args_of(TABLE + (0.0,), NEAR_WALL + (0.0,)))
        self.assertEqual(len(lines), 2, lines)
        self.assertIn(': ABORTED after', lines[0])
        self.assertIn('refused: ', lines[0])
        self.assertIn(': ABORTED after', lines[1])
        self.assertIn('no path: ', lines[1])
        self.assertEqual(rc, 1)

    def test_3_a_canceled_goal_then_the_next(self):
        rc, lines = self.client('--cancel-after', '1', *args_of(OTHER_SIDE + (0.0,),
                                                                  TABLE + (0.0,)))
        self.assertEqual(len(lines), 2, lines)
        self.assertIn(': PREEMPTED after', lines[0])
        self.assertIn(': ABORTED after', lines[1])
        self.assertEqual(rc, 1)

    def test_4_a_goal_without_a_result_in_time_is_canceled_before_the_next(self):
        # Left running, the first goal would be preempted by the second on the server, and the
        # client would hear of a goal it no longer tracks.
        rc, lines = self.client('--timeout', '1', *args_of(OTHER_SIDE + (0.0,), TABLE + (0.0,)))
        self.assertEqual(len(lines), 2, lines)
        self.assertIn(': PREEMPTED after', lines[0])
        self.assertIn('(canceled: no result within 1 s)', lines[0])
        self.assertIn(': ABORTED after', lines[1])
        self.assertEqual(rc, 1)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_move_base_client', TestMoveBaseClient)
