#!/usr/bin/python3
"""world_view.launch gazebo_world:=worlds/furnished_room.world: /jetbot/map is the room cut at the
scanner's height (its extent, walls, table legs, the counter's L with its notch free, the table
tops above the cut), /jetbot/world_geometry shows its shapes, the scan sees the closed room, and
the two robots start apart (issue 50: at one point, the tribot hid the Jetbot in RViz)."""
import math
import unittest

import rospy
import rostest
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan
from visualization_msgs.msg import Marker, MarkerArray

from jetbot_rl_test.world_view import start_apart

TIMEOUT = 30.0


def cell(grid, x, y):
    """The value of the cell holding (x, y) [m, map frame]."""
    i = int(math.floor((x - grid.info.origin.position.x) / grid.info.resolution))
    j = int(math.floor((y - grid.info.origin.position.y) / grid.info.resolution))
    return grid.data[j * grid.info.width + i]


class TestGazeboWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_gazebo_world')

    def test_apart_at_the_start(self):
        start_apart(self)

    def test_map_is_the_room_cut_at_the_scanner(self):
        grid = rospy.wait_for_message('/jetbot/map', OccupancyGrid, TIMEOUT)
        self.assertEqual(grid.header.frame_id, 'jetbot/env_0/map')
        self.assertAlmostEqual(grid.info.resolution, 0.05, places=6)
        # The walls' outer faces at x = +-3.1, y = +-2.6, and 1 m of free cells around them.
        self.assertAlmostEqual(grid.info.origin.position.x, -4.1, places=6)
        self.assertAlmostEqual(grid.info.origin.position.y, -3.6, places=6)
        self.assertEqual((grid.info.width, grid.info.height), (164, 144))
        self.assertTrue(all(v in (0, 100) for v in grid.data))
        occupied = {
            'east wall': (3.05, 0.0), 'north wall': (0.0, 2.55), 'a table leg': (1.05, 1.05),
            "the counter's long arm": (-2.0, -2.2), "the counter's short arm": (-2.8, -1.6),
            'the sofa': (1.2, -0.9), 'the ball': (-0.7, -1.3), 'the lying barrel': (-1.1, -0.3),
            'the polyline pillar': (2.4, -1.5)}
        for what, (x, y) in occupied.items():
            self.assertEqual(cell(grid, x, y), 100, what)
        free = {'the spawn': (0.0, 0.0), "the counter's notch": (-2.0, -1.6),
                'under a table top': (1.6, 1.4), 'outside the room': (-3.8, 0.0)}
        for what, (x, y) in free.items():
            self.assertEqual(cell(grid, x, y), 0, what)

    def test_markers_show_the_shapes(self):
        msg = rospy.wait_for_message('/jetbot/world_geometry', MarkerArray, TIMEOUT)
        kinds = [m.type for m in msg.markers]
        # 4 walls, 2 sofa boxes; 8 table legs and the side table; the rest as one triangle list.
        self.assertEqual(kinds.count(Marker.CUBE), 6)
        self.assertEqual(kinds.count(Marker.CYLINDER), 9)
        self.assertEqual(kinds.count(Marker.TRIANGLE_LIST), 1)
        surfaces = [m for m in msg.markers if m.type == Marker.TRIANGLE_LIST][0]
        self.assertEqual(len(surfaces.points) % 3, 0)
        self.assertGreater(len(surfaces.points), 3 * 20)
        for m in msg.markers:
            self.assertEqual(m.header.frame_id, 'jetbot/env_0/map')

    def test_scans_see_the_closed_room(self):
        for robot in ('jetbot', 'tribot'):
            scan = rospy.wait_for_message('/%s/env_0/scan' % robot, LaserScan, TIMEOUT)
            # From the spawn every beam meets a wall or furniture within 3.95 m (the far
            # corners); the tribot's 3.5 m scanner misses only towards the corners.
            for r in scan.ranges:
                self.assertTrue(math.isinf(r) or scan.range_min <= r <= 3.95, (robot, r))
            self.assertGreater(sum(1 for r in scan.ranges if math.isfinite(r)),
                               0.75 * len(scan.ranges))


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'gazebo_world', TestGazeboWorld)
