#!/usr/bin/python3
"""A TurtleBot3 Waffle with the R200 block as ROBOTIS publishes it (image set to 640 x 480) in a
3 x 3 m room, realtime mode: env_0/camera/rgb/image_raw (rgb8) and env_0/camera/depth/image_raw
(32FC1) in camera_rgb_optical_frame at the plugin's 30 Hz, CameraInfo from the fov, and the depth
at the image centre equal to what the laser scanner measures ahead, corrected for where the two
sensors sit (tf), within 3 cm."""
import math
import threading
import time
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from sensor_msgs.msg import CameraInfo, Image, LaserScan

from jetbot_rl_test.env_client import notify, wait_for

TIMEOUT = 30.0
HFOV = 1.3439
WIDTH, HEIGHT = 640, 480
CONTROL_DT = 1.0 / 60.0


class TestCameraView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_camera_view')
        cls.lock = threading.Lock()
        cls.received = {'rgb': [], 'depth': [], 'scan': []}
        for key, topic, kind in (('rgb', '/env_0/camera/rgb/image_raw', Image),
                                 ('depth', '/env_0/camera/depth/image_raw', Image),
                                 ('scan', '/env_0/scan', LaserScan)):
            rospy.Subscriber(topic, kind, cls.keep(key), queue_size=200)

    @classmethod
    def keep(cls, key):
        def on_message(msg):
            with cls.lock:
                cls.received[key].append((time.monotonic(), msg))
            notify()
        return on_message

    def messages(self, key):
        with self.lock:
            return list(self.received[key])

    def test_images_as_the_openni_plugin_names_them(self):
        wait_for(lambda: self.messages('rgb') and self.messages('depth'), TIMEOUT, 'the images')
        rgb = self.messages('rgb')[-1][1]
        depth = self.messages('depth')[-1][1]
        for image, encoding, size in ((rgb, 'rgb8', 3), (depth, '32FC1', 4)):
            self.assertEqual(image.header.frame_id, 'env_0/camera_rgb_optical_frame')
            self.assertEqual(image.encoding, encoding)
            self.assertEqual((image.width, image.height), (WIDTH, HEIGHT))
            self.assertEqual(image.step, WIDTH * size)
            self.assertEqual(len(image.data), WIDTH * HEIGHT * size)
        # The floor and the 0.5 m walls below the horizon: finite, within the room's diagonal;
        # above the walls nothing within the far clip: +inf (REP 118).
        d = np.frombuffer(depth.data, np.float32).reshape(HEIGHT, WIDTH)
        self.assertTrue(np.all(np.isfinite(d[HEIGHT // 2:])))
        self.assertLess(float(d[HEIGHT // 2:].max()), 3.0 * math.sqrt(2.0))
        self.assertTrue(np.all(d[0] == np.inf))
        # Floor, walls and sky are different colours, not one flat fill.
        self.assertGreaterEqual(len(np.unique(np.frombuffer(rgb.data, np.uint8).reshape(-1, 3),
                                              axis=0)), 3)

    def test_camera_info_from_the_fov(self):
        for topic in ('/env_0/camera/rgb/camera_info', '/env_0/camera/depth/camera_info'):
            info = rospy.wait_for_message(topic, CameraInfo, TIMEOUT)
            f = WIDTH / 2.0 / math.tan(HFOV / 2.0)
            self.assertEqual(info.header.frame_id, 'env_0/camera_rgb_optical_frame')
            self.assertEqual((info.width, info.height), (WIDTH, HEIGHT))
            self.assertEqual(info.distortion_model, 'plumb_bob')
            self.assertEqual(list(info.D), [0.0] * 5)
            for got, want in zip(info.K, [f, 0, (WIDTH - 1) / 2.0, 0, f, (HEIGHT - 1) / 2.0,
                                          0, 0, 1]):
                self.assertAlmostEqual(got, want, places=6)
            self.assertAlmostEqual(info.P[0], f, places=6)

    def test_images_at_the_plugins_rate(self):
        # <updateRate> 30 Hz at a 60 Hz control step: an image every 2 control steps of
        # simulation time, and at least 10 a second of wall time in realtime mode.
        wait_for(lambda: len(self.messages('depth')) >= 40, TIMEOUT, '40 depth images')
        for key in ('rgb', 'depth'):
            got = self.messages(key)
            stamps = [m.header.stamp.to_sec() for _, m in got]
            gaps = [b - a for a, b in zip(stamps, stamps[1:])]
            self.assertTrue(gaps)
            for gap in gaps:
                self.assertAlmostEqual(gap / (2 * CONTROL_DT), round(gap / (2 * CONTROL_DT)),
                                       places=3)
                self.assertGreaterEqual(round(gap / (2 * CONTROL_DT)), 1)
            wall = got[-1][0] - got[0][0]
            print('FIGURE: %s %.1f images/s of wall time' % (key, (len(got) - 1) / wall))
            self.assertGreaterEqual((len(got) - 1) / wall, 10.0, key)

    def test_centre_depth_equals_the_scanners_range(self):
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        t = buffer.lookup_transform('env_0/base_footprint', 'env_0/camera_rgb_optical_frame',
                                    rospy.Time(0), rospy.Duration(TIMEOUT))
        s = buffer.lookup_transform('env_0/base_footprint', 'env_0/base_scan', rospy.Time(0),
                                    rospy.Duration(TIMEOUT))
        wait_for(lambda: len(self.messages('scan')) >= 5 and self.messages('depth'), TIMEOUT,
                 '5 scans and a depth image')
        # The robot stands still facing the wall ahead (+x): beam 0 of the scan (angle 0) and the
        # optical axis both run along x; the wall lies at scan x + range in the robot's frame.
        scan = self.messages('scan')[-5:]
        self.assertAlmostEqual(scan[-1][1].angle_min, 0.0)
        ahead = float(np.mean([m.ranges[0] for _, m in scan]))
        wall_x = s.transform.translation.x + ahead
        depth = self.messages('depth')[-1][1]
        d = np.frombuffer(depth.data, np.float32).reshape(HEIGHT, WIDTH)
        centre = float(d[HEIGHT // 2 - 1:HEIGHT // 2 + 1, WIDTH // 2 - 1:WIDTH // 2 + 1].mean())
        expected = wall_x - t.transform.translation.x
        print('FIGURE: centre depth %.4f m, the laser scanner gives %.4f m' % (centre, expected))
        self.assertAlmostEqual(centre, expected, delta=0.03)
        self.assertGreater(centre, 1.0)


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_camera_view', TestCameraView)
