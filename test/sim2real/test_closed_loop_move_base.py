#!/usr/bin/python3
"""The learnt navigator behind the move_base action, as a mission script drives it: the shipped
arena navigator (policies/navigation_arena: 200 iterations, no path observed) on the env
node's lidar Jetbot in the office map, through jetbot_deploy_node's move_base action
(actionlib's SimpleActionClient, move_base_msgs/MoveBaseAction). Quiet while idle; goals in an
obstacle, in an unknown frame or too near a wall ABORTED at once with the reason and the robot
still; a goal behind a wall SUCCEEDED through the door (a plan, the policy following a carrot
along it) at the goal's heading, with feedback; a new goal preempting the current one; a cancel
stopping the robot at once; a robot whose wheels get no commands stuck, recovering, then
ABORTED; a robot boxed in (its scan) after the plan recovering, then ABORTED; a mission script
killed mid-goal leaving the robot stopped."""
import math
import subprocess
import time

import actionlib
import rostest
import rospy
from actionlib_msgs.msg import GoalStatus, GoalStatusArray
from geometry_msgs.msg import Twist
from move_base_msgs.msg import MoveBaseAction
from nav_msgs.msg import Path
from sensor_msgs.msg import LaserScan

from jetbot_rl.move_base_goal import move_base_goal
from jetbot_rl_test.deployed_navigation import DeployedNavigation
from jetbot_rl_test.env_client import TIMEOUT, EventList, wait_for
from jetbot_rl_test.robot_view_client import yaw

ABOVE = (0.0, 2.0)        # the room above, behind the wall at y = 0.5 (door at x in [1, 2])
OTHER_SIDE = (-3.0, 0.0)  # the left half, behind the wall at x = -1
TABLE = (2.25, -2.0)      # in the table
NEAR_WALL = (-0.87, 2.0)  # a free cell 3 cm from a wall: within the footprint
REACH_WITHIN = 90.0       # [s]


def action_goal(x, y, heading=0.0, frame='env_0/map'):
    return move_base_goal(x, y, heading, frame)


def is_zero(twist):
    return twist.linear.x == 0.0 and twist.angular.z == 0.0


class TestClosedLoopMoveBase(DeployedNavigation):
    node_name = 'test_closed_loop_move_base'

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.twists = EventList()
        rospy.Subscriber('/env_0/cmd_vel', Twist,
                         lambda m: cls.twists.append((time.monotonic(), m)), tcp_nodelay=True)
        cls.statuses = EventList()
        rospy.Subscriber('/move_base/status', GoalStatusArray, cls.statuses.append)

    def result(self, client, goal, within, feedback=None):
        """Sends `goal`, waits for its end; returns (state, text, seconds)."""
        sent = time.monotonic()
        client.send_goal(goal, feedback_cb=feedback)
        self.assertTrue(client.wait_for_result(rospy.Duration(within)),
                        'no result within %.0f s' % within)
        return client.get_state(), client.get_goal_status_text(), time.monotonic() - sent

    def moving(self):
        return abs(self.odoms[-1].twist.twist.linear.x) > 0.05

    def test_1_quiet_while_idle(self):
        wait_for(lambda: len(self.odoms) > 0, what='odometry')
        count, seen = len(self.twists), len(self.odoms)
        wait_for(lambda: len(self.odoms) > seen + 100, what='two seconds of odometry')
        print('FIGURE: move_base: %d Twists in 2 s while idle' % (len(self.twists) - count))
        self.assertLessEqual(len(self.twists) - count, 1)

    def test_2_bad_goals_abort_at_once(self):
        start = self.position()
        for goal, text in ((action_goal(*TABLE), 'refused: '),
                           (action_goal(*ABOVE, frame='nowhere'), 'refused: cannot transform'),
                           (action_goal(*NEAR_WALL), 'no path: ')):
            state, why, took = self.result(self.client, goal, 5.0)
            print('FIGURE: move_base: a bad goal ended (state %d) after %.2f s: %s'
                  % (state, took, why))
            self.assertEqual(state, GoalStatus.ABORTED, why)
            self.assertTrue(why.startswith(text), why)
        self.assertIn('footprint', why)
        self.assert_still(start)

    def test_3_a_goal_behind_a_wall_succeeds_at_its_heading(self):
        heading = 0.5 * math.pi
        start, first_scan, plans = self.position(), len(self.scans), len(self.plans)
        feedback = EventList()
        state, why, took = self.result(self.client, action_goal(*ABOVE, heading=heading),
                                       REACH_WITHIN, feedback.append)
        self.assertEqual(state, GoalStatus.SUCCEEDED, why)
        x, y = self.position()
        error = abs(math.atan2(math.sin(yaw(self.odoms[-1].pose.pose.orientation) - heading),
                               math.cos(yaw(self.odoms[-1].pose.pose.orientation) - heading)))
        closest = min(min(r for r in s.ranges) for s in self.scans[first_scan:])
        print('FIGURE: move_base: goal (%.1f, %.1f, %.2f rad) behind a wall SUCCEEDED in %.1f s '
              'at (%.2f, %.2f), heading %.3f rad off; %d feedbacks; closest scan reading %.3f m'
              % (ABOVE[0], ABOVE[1], heading, took, x, y, error, len(feedback), closest))
        self.assertLess(math.hypot(x - ABOVE[0], y - ABOVE[1]), 0.3)
        self.assertLess(error, 0.1 + 0.05)
        self.assertGreater(closest, float('-inf'), 'a scan read below range_min: a touch')
        self.assertTrue(feedback)
        p = feedback[-1].base_position.pose.position
        self.assertLess(math.hypot(p.x - x, p.y - y), 0.3)
        # The first plan with poses: an empty one ended the previous goal.
        plan = next(([(q.pose.position.x, q.pose.position.y) for q in p.poses]
                     for p in self.plans[plans:] if p.poses), [])
        self.assertGreaterEqual(len(plan), 3, plan)  # round the wall
        self.assertLess(math.hypot(plan[0][0] - start[0], plan[0][1] - start[1]), 0.3)
        self.assertTrue(any(s.status_list for s in self.statuses), 'nothing on move_base/status')

    def test_4_a_new_goal_preempts_the_current_one(self):
        other = actionlib.SimpleActionClient('move_base', MoveBaseAction)
        self.assertTrue(other.wait_for_server(rospy.Duration(TIMEOUT)))
        other.send_goal(action_goal(*OTHER_SIDE))
        wait_for(self.moving, what='the robot to drive to the first goal')
        near = (1.0, 2.0)  # in the room above, where the robot is
        state, why, took = self.result(self.client, action_goal(*near), REACH_WITHIN)
        self.assertEqual(state, GoalStatus.SUCCEEDED, why)
        wait_for(lambda: other.get_state() != GoalStatus.ACTIVE, what='the first goal to end')
        print('FIGURE: move_base: the first goal %d (%s), the second SUCCEEDED in %.1f s'
              % (other.get_state(), other.get_goal_status_text(), took))
        self.assertEqual(other.get_state(), GoalStatus.PREEMPTED)

    def test_5_cancel_stops_the_robot_at_once(self):
        self.client.send_goal(action_goal(*OTHER_SIDE))
        wait_for(self.moving, what='the robot to drive')
        count = len(self.twists)
        canceled = time.monotonic()
        self.client.cancel_goal()
        wait_for(lambda: any(is_zero(m) for _, m in self.twists[count:]),
                 what='a zero Twist after the cancel')
        stopped = next(t for t, m in self.twists[count:] if is_zero(m)) - canceled
        wait_for(lambda: self.client.get_state() != GoalStatus.ACTIVE, what='the goal to end')
        self.assertEqual(self.client.get_state(), GoalStatus.PREEMPTED)
        seen = len(self.odoms)
        wait_for(lambda: len(self.odoms) > seen + 25, what='half a second of odometry')
        speed = abs(self.odoms[-1].twist.twist.linear.x)
        print('FIGURE: move_base: a zero Twist %.3f s after the cancel; %.3f m/s 0.5 s later'
              % (stopped, speed))
        self.assertLess(stopped, 0.25)
        self.assertTrue(all(is_zero(m) for _, m in self.twists[count:][-1:]))
        self.assertLess(speed, 0.02)

    def test_6_a_stuck_robot_recovers_then_aborts(self):
        # A second navigator whose Twists reach no wheels: the robot cannot move.
        stuck = self.deploy('stuck', ['_cmd_vel_topic:=/nowhere/cmd_vel',
                                      '_action_name:=stuck_move_base', '_goal_topic:=~goal',
                                      '_oscillation_timeout:=1.5', '_max_recoveries:=1',
                                      '_recovery_backoff:=0.1'])
        try:
            client = actionlib.SimpleActionClient('stuck_move_base', MoveBaseAction)
            self.assertTrue(client.wait_for_server(rospy.Duration(TIMEOUT)))
            state, why, took = self.result(client, action_goal(*OTHER_SIDE), 30.0)
            print('FIGURE: move_base: a robot that cannot move ABORTED after %.1f s: %s'
                  % (took, why))
            self.assertEqual(state, GoalStatus.ABORTED, why)
            self.assertIn('stuck: moved less than', why)
            self.assertIn('after 1 recoveries', why)
        finally:
            stuck.terminate()
            stuck.wait(timeout=TIMEOUT)

    def test_6b_a_way_blocked_after_the_plan_recovers_then_aborts(self):
        # A second navigator on the same robot whose scan the test relays; once it drives, the
        # relay boxes it in (every reading at most 0.35 m): what the scan sees blocks the plan,
        # and no re-plan finds a way out.
        boxed_in = []

        def relay(scan):
            if boxed_in:
                scan.ranges = [min(r, 0.35) for r in scan.ranges]
            boxed_scan.publish(scan)

        boxed_scan = rospy.Publisher('/boxed/scan', LaserScan, queue_size=1)
        relay_sub = rospy.Subscriber('/env_0/scan', LaserScan, relay)
        boxed = self.deploy('boxed', ['_scan_topic:=/boxed/scan',
                                      '_action_name:=boxed_move_base', '_goal_topic:=~goal',
                                      '_max_recoveries:=1', '_max_planning_retries:=1'])
        plans = EventList()
        plan_sub = rospy.Subscriber('/boxed/plan', Path, plans.append)
        try:
            client = actionlib.SimpleActionClient('boxed_move_base', MoveBaseAction)
            self.assertTrue(client.wait_for_server(rospy.Duration(TIMEOUT)))
            sent = time.monotonic()
            client.send_goal(action_goal(*OTHER_SIDE))
            wait_for(lambda: any(p.poses for p in plans), what='a plan')
            wait_for(self.moving, what='the robot to drive')
            boxed_in.append(True)
            self.assertTrue(client.wait_for_result(rospy.Duration(60.0)), 'no result in 60 s')
            state, why = client.get_state(), client.get_goal_status_text()
            took = time.monotonic() - sent
            seen = len(self.odoms)
            wait_for(lambda: len(self.odoms) > seen + 50, what='a second of odometry')
            speed = abs(self.odoms[-1].twist.twist.linear.x)
            wait_for(lambda: not plans[-1].poses, what='the plan to be emptied')
            print('FIGURE: move_base: boxed in after the plan: ABORTED after %.1f s (%s); '
                  '%.3f m/s a second later' % (took, why, speed))
            self.assertEqual(state, GoalStatus.ABORTED, why)
            self.assertIn('no path', why)
            self.assertIn('max_planning_retries', why)
            self.assertIn('after 1 recoveries', why)
            self.assertLess(speed, 0.02)
        finally:
            relay_sub.unregister()
            plan_sub.unregister()
            boxed.terminate()
            boxed.wait(timeout=TIMEOUT)

    def test_7_a_killed_client_leaves_the_robot_stopped(self):
        # The shipped mission script, killed mid-goal: nothing can cancel its goal any more.
        mission = subprocess.Popen(['rosrun', 'jetbot_rl', 'move_base_client.py',
                                    str(OTHER_SIDE[0]), str(OTHER_SIDE[1])])
        try:
            wait_for(self.moving, what='the robot to drive to the script\'s goal')
            count, outcomes = len(self.twists), len(self.outcomes)
            killed = time.monotonic()
            mission.kill()
            mission.wait(timeout=TIMEOUT)
        finally:
            if mission.poll() is None:
                mission.kill()
        wait_for(lambda: any(is_zero(m) for _, m in self.twists[count:]),
                 what='a zero Twist after the client died')
        stopped = next(t for t, m in self.twists[count:] if is_zero(m)) - killed
        wait_for(lambda: len(self.outcomes) > outcomes, what='the goal\'s end')
        seen = len(self.odoms)
        wait_for(lambda: len(self.odoms) > seen + 50, what='a second of odometry')
        speed = abs(self.odoms[-1].twist.twist.linear.x)
        print('FIGURE: move_base: client killed mid-goal: a zero Twist %.3f s later (%s); '
              '%.3f m/s a second later' % (stopped, self.outcomes[outcomes], speed))
        self.assertIn('disconnected', self.outcomes[outcomes])
        self.assertLess(stopped, 0.5)
        self.assertTrue(all(is_zero(m) for _, m in self.twists[count:][-1:]))
        self.assertLess(speed, 0.02)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_closed_loop_move_base', TestClosedLoopMoveBase)
