#!/usr/bin/python3
"""The env node with a map, random obstacles and the lidar Jetbot: /map is the grid map_server
would serve for maps/office.yaml (decoded here independently), tf places each env's map frame,
env_0/scan comes in the scanner link's frame with the Gazebo block's angles and ranges, at its
rate (every 11 control steps: 5.5 Hz at 60 Hz), and the markers show the world."""
import math
import os
import threading
import unittest

import numpy as np
import rospkg
import rospy
import rostest
import tf2_ros
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan
from visualization_msgs.msg import MarkerArray

from jetbot_rl_test.env_client import EnvClient, wait_for

PKG = rospkg.RosPack().get_path('jetbot_rl')
TIMEOUT = 30.0
CONTROL_DT = 1.0 / 60.0


def office_grid():
    """maps/office.pgm as map_server's trinary loader turns it into cells (lower-left first)."""
    with open(os.path.join(PKG, 'maps', 'office.pgm'), 'rb') as f:
        data = f.read()
    fields, offset = [], 0
    while len(fields) < 4:  # P5, width, height, maxval; comment lines skipped
        end = data.index(b'\n', offset)
        line = data[offset:end].split(b'#')[0].split()
        fields += line
        offset = end + 1
    width, height = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data[offset:offset + width * height], np.uint8).reshape(height, width)
    occ = (255.0 - pixels) / 255.0
    cells = np.where(occ > 0.65, 100, np.where(occ < 0.196, 0, -1)).astype(np.int8)
    return width, height, cells[::-1].flatten()


class TestWorldScan(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_world_scan')
        cls.lock = threading.Lock()
        cls.scans = []
        cls.scan_sub = rospy.Subscriber('/env_0/scan', LaserScan, cls.on_scan, queue_size=100)
        cls.env = EnvClient()

    @classmethod
    def on_scan(cls, msg):
        with cls.lock:
            cls.scans.append(msg)

    def test_map_is_the_files_grid(self):
        grid = rospy.wait_for_message('/map', OccupancyGrid, TIMEOUT)
        width, height, cells = office_grid()
        self.assertEqual(grid.header.frame_id, 'env_0/map')
        self.assertEqual((grid.info.width, grid.info.height), (width, height))
        self.assertAlmostEqual(grid.info.resolution, 0.05, places=6)
        self.assertAlmostEqual(grid.info.origin.position.x, -5.0)
        self.assertAlmostEqual(grid.info.origin.position.y, -4.0)
        self.assertAlmostEqual(grid.info.origin.orientation.w, 1.0)
        self.assertEqual(bytes(np.array(grid.data, np.int8).tobytes()), cells.tobytes())
        self.assertGreater(int(np.sum(cells == 100)), 500)
        # Every env's map frame hangs from world at its origin; odom coincides with it.
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        for env in (0, 1):
            t = buffer.lookup_transform('env_%d/map' % env, 'env_%d/odom' % env, rospy.Time(0),
                                        rospy.Duration(TIMEOUT))
            self.assertAlmostEqual(t.transform.translation.x, 0.0)
            buffer.lookup_transform('world', 'env_%d/map' % env, rospy.Time(0),
                                    rospy.Duration(TIMEOUT))

    def test_scan_frame_angles_ranges_and_rate(self):
        state = self.env.current()
        steps = 45
        for k in range(steps):
            state = self.env.step_service(state.step, [5.0] * 4).state
        last = state.step
        wait_for(lambda: self.scans and self.scans[-1].header.stamp.to_sec() >=
                 (last // 11 * 11) * CONTROL_DT - 1e-6, what='the scans of the steps')
        with self.lock:
            scans = list(self.scans)
        s = scans[-1]
        self.assertEqual(s.header.frame_id, 'env_0/lidar_link')
        self.assertEqual(len(s.ranges), 360)
        self.assertAlmostEqual(s.angle_min, -3.14159, places=5)
        self.assertAlmostEqual(s.angle_max, 3.12414, places=5)
        self.assertAlmostEqual(s.angle_increment, (3.12414 + 3.14159) / 359, places=6)
        self.assertAlmostEqual(s.range_min, 0.15, places=6)
        self.assertAlmostEqual(s.range_max, 12.0, places=6)
        self.assertAlmostEqual(s.scan_time, 11 * CONTROL_DT, places=6)
        # One scan every 11 control steps of simulation time.
        stamps = [m.header.stamp.to_sec() for m in scans]
        gaps = [b - a for a, b in zip(stamps, stamps[1:]) if b > a]
        self.assertGreaterEqual(len(gaps), steps // 11 - 1)
        for gap in gaps:
            self.assertAlmostEqual(gap, 11 * CONTROL_DT, places=4)
        # In the closed office every beam ends on a wall or an obstacle within 12 m: finite, or
        # -inf when something is closer than range_min; +inf only for a beam that finds nothing.
        finite = [r for r in s.ranges if math.isfinite(r)]
        self.assertGreater(len(finite), 300)
        for r in s.ranges:
            self.assertTrue(r == float('inf') or r == float('-inf') or 0.15 <= r <= 12.0, r)

    def test_markers_show_the_walls_and_obstacles(self):
        def world_markers():
            msg = rospy.wait_for_message('/jetbot_env/markers', MarkerArray, TIMEOUT)
            return [m for m in msg.markers if m.ns == 'world']
        markers = world_markers()
        # Per env: the 4 arena walls and 5 obstacles (config/world_obstacles.yaml).
        self.assertEqual(len(markers), 2 * (4 + 5))
        self.assertTrue(any(m.type == m.CYLINDER for m in markers))


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_world_scan', TestWorldScan)
