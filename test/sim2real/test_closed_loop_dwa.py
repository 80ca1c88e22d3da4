#!/usr/bin/python3
"""Closed loop with the classical baseline, as on a robot: jetbot_deploy_node with
`local_planner: dwa` drives the env node's lidar Jetbot in the office map by the dynamic window
approach (move_base's dwa_local_planner, the navigation benchmark's `dwa` rows) along the plan it
makes on /map; the shipped navigator's checkpoint gives the footprint, goal radius, control rate
and top speed, and its policy does not act (the DWA's footprint padded to the lidar's range_min).
Its status says the DWA drives; a goal behind a wall, in the room above, is reached through the
door within a time bound without coming nearer anything than the lidar's range_min."""
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray

from jetbot_rl_test.deployed_navigation import DeployedNavigation
from jetbot_rl_test.env_client import EventList, wait_for

ABOVE = (0.0, 2.0)  # env frame (= env_0/map): the room above, behind the wall at y = 0.5


class TestClosedLoopDwa(DeployedNavigation):
    node_name = 'test_closed_loop_dwa'
    shipped_policy = 'navigation'
    # The lidar's range_min (0.15 m) exceeds the footprint (0.106 m): nearer, a wall reads -inf.
    # Padded by the difference, the DWA keeps out of the band where the scan is blind; its local
    # goal 1 m along the plan (the default 2 m drew it across the door's jamb, where it stuck).
    deploy_args = ['_local_planner:=dwa', '_dwa/footprint_padding:=0.05',
                   '_dwa/local_goal_distance:=1.0']

    @classmethod
    def setUpClass(cls):
        cls.statuses = EventList()
        super().setUpClass()
        rospy.Subscriber('/diagnostics', DiagnosticArray, lambda m: cls.statuses.extend(
            s for s in m.status if s.name == '/deploy: deploy'))

    def test_1_the_status_says_the_dwa_drives(self):
        wait_for(lambda: self.statuses, what="the deploy node's status")
        values = {kv.key: kv.value for kv in self.statuses[-1].values}
        self.assertEqual(values.get('local planner'), 'dwa', values)
        self.assertIn('dwa steps without a clear trajectory', values)

    def test_2_a_goal_behind_a_wall_is_reached_through_the_door(self):
        self.reach(ABOVE, 'dwa closed loop')


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_closed_loop_dwa', TestClosedLoopDwa)
