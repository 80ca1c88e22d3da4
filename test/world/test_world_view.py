#!/usr/bin/python3
"""launch/world_view.launch: the Jetbot with its RPLIDAR-like block and the tribot with its
TurtleBot3-form Gazebo block, in realtime mode in the office map, start apart, keep their names
apart (robot_prefix jetbot/ and tribot/: topics, frames), scan as their Gazebo blocks say, and
drive by hand through cmd_vel."""
import math
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan

from jetbot_rl_test.world_view import start_apart

TIMEOUT = 30.0


class TestWorldView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_world_view')

    def test_apart_at_the_start(self):
        start_apart(self)

    def test_each_robot_scans_as_its_gazebo_block_says(self):
        jetbot = rospy.wait_for_message('/jetbot/env_0/scan', LaserScan, TIMEOUT)
        tribot = rospy.wait_for_message('/tribot/env_0/scan', LaserScan, TIMEOUT)
        self.assertEqual(jetbot.header.frame_id, 'jetbot/env_0/lidar_link')
        self.assertEqual(tribot.header.frame_id, 'tribot/env_0/base_scan')
        self.assertEqual(len(jetbot.ranges), 360)
        self.assertAlmostEqual(jetbot.range_max, 12.0, places=5)
        # The tribot's block is TurtleBot3's: 360 beams over [0, 6.28319] rad, 0.12 to 3.5 m.
        self.assertEqual(len(tribot.ranges), 360)
        self.assertAlmostEqual(tribot.angle_min, 0.0)
        self.assertAlmostEqual(tribot.angle_max, 6.28319, places=5)
        self.assertAlmostEqual(tribot.range_min, 0.12, places=5)
        self.assertAlmostEqual(tribot.range_max, 3.5, places=5)
        self.assertAlmostEqual(tribot.scan_time, 12 / 60.0, places=5)  # 5 Hz
        # Both in the same office: the walls within a few metres.
        for scan in (jetbot, tribot):
            self.assertGreater(sum(1 for r in scan.ranges if math.isfinite(r)), 100)

    def test_maps_and_frames_are_apart(self):
        for robot in ('jetbot', 'tribot'):
            grid = rospy.wait_for_message('/%s/map' % robot, OccupancyGrid, TIMEOUT)
            self.assertEqual(grid.header.frame_id, '%s/env_0/map' % robot)
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        buffer.lookup_transform('world', 'jetbot/env_0/base_link', rospy.Time(0),
                                rospy.Duration(TIMEOUT))
        buffer.lookup_transform('world', 'tribot/env_0/base_footprint', rospy.Time(0),
                                rospy.Duration(TIMEOUT))

    def test_driving_by_hand(self):
        start = rospy.wait_for_message('/jetbot/env_0/odom', Odometry, TIMEOUT).pose.pose.position
        pub = rospy.Publisher('/jetbot/env_0/cmd_vel', Twist, queue_size=1)
        twist = Twist()
        twist.linear.x = 0.2
        # cmd_vel is a stream (as from a teleop node): 20 Hz until the robot has moved 5 cm.
        rate = rospy.Rate(20)
        deadline = rospy.get_time() + TIMEOUT
        moved = 0.0
        while moved < 0.05 and rospy.get_time() < deadline:
            pub.publish(twist)
            rate.sleep()
            odom = rospy.wait_for_message('/jetbot/env_0/odom', Odometry, TIMEOUT)
            p = odom.pose.pose.position
            moved = math.hypot(p.x - start.x, p.y - start.y)
        self.assertGreater(moved, 0.05)
        self.assertGreater(odom.twist.twist.linear.x, 0.1)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_world_view', TestWorldView)
