#!/usr/bin/python3
"""The Jetbot with the IMX219-83 stereo module (urdf/jetbot_stereo.urdf) in a 3 x 3 m room,
realtime mode: env_0/stereo/left/image_raw and env_0/stereo/right/image_raw (rgb8), their depth
images and CameraInfo as gazebo_ros_multicamera names them, each camera in its own optical frame,
60 mm apart in tf, and the two depth images agreeing as two views of one room: a point the left
camera sees lands, moved by the baseline, where the right camera sees the same depth."""
import math
import threading
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros
from sensor_msgs.msg import CameraInfo, Image

from jetbot_rl_test.env_client import notify, wait_for

TIMEOUT = 30.0
WIDTH, HEIGHT = 320, 240
HFOV = 1.2319
BASELINE = 0.06
SIDES = ('left', 'right')


class TestStereoView(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_stereo_view')
        cls.lock = threading.Lock()
        cls.latest = {}
        for side in SIDES:
            for kind, topic in (('rgb', 'image_raw'), ('depth', 'depth/image_raw')):
                rospy.Subscriber('/env_0/stereo/%s/%s' % (side, topic), Image,
                                 cls.keep((side, kind)), queue_size=4)

    @classmethod
    def keep(cls, key):
        def on_message(msg):
            with cls.lock:
                cls.latest[key] = msg
            notify()
        return on_message

    def image(self, side, kind):
        with self.lock:
            return self.latest.get((side, kind))

    def both_depths(self):
        """A left and a right depth image of one instant (the robot stands still)."""
        def same_stamp():
            left, right = self.image('left', 'depth'), self.image('right', 'depth')
            return left is not None and right is not None and \
                left.header.stamp == right.header.stamp
        wait_for(same_stamp, TIMEOUT, 'a left and a right depth image of one stamp')
        return [np.frombuffer(self.image(side, 'depth').data, np.float32).reshape(HEIGHT, WIDTH)
                for side in SIDES]

    def test_each_camera_where_the_multicamera_plugin_publishes_it(self):
        wait_for(lambda: all(self.image(s, k) for s in SIDES for k in ('rgb', 'depth')),
                 TIMEOUT, 'both cameras\' images')
        for side in SIDES:
            frame = 'env_0/camera_link_%s_optical_frame' % side
            for kind, encoding in (('rgb', 'rgb8'), ('depth', '32FC1')):
                image = self.image(side, kind)
                self.assertEqual(image.header.frame_id, frame)
                self.assertEqual(image.encoding, encoding)
                self.assertEqual((image.width, image.height), (WIDTH, HEIGHT))
            info = rospy.wait_for_message('/env_0/stereo/%s/camera_info' % side, CameraInfo,
                                          TIMEOUT)
            self.assertEqual(info.header.frame_id, frame)
            self.assertAlmostEqual(info.K[0], WIDTH / 2.0 / math.tan(HFOV / 2.0), places=6)

    def test_the_optical_frames_stand_the_baseline_apart(self):
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        t = buffer.lookup_transform('env_0/camera_link_left_optical_frame',
                                    'env_0/camera_link_right_optical_frame', rospy.Time(0),
                                    rospy.Duration(TIMEOUT))
        # The right camera lies along the left one's x axis (x right, REP 103 optical).
        got = [t.transform.translation.x, t.transform.translation.y, t.transform.translation.z]
        for value, want in zip(got, [BASELINE, 0.0, 0.0]):
            self.assertAlmostEqual(value, want, places=9)
        self.assertAlmostEqual(t.transform.rotation.w, 1.0, places=9)

    def test_the_two_views_agree(self):
        left, right = self.both_depths()
        f = WIDTH / 2.0 / math.tan(HFOV / 2.0)
        cx, cy = (WIDTH - 1) / 2.0, (HEIGHT - 1) / 2.0

        def agreement(baseline):
            """The share of the left camera's finite pixels whose point, seen from a camera
            `baseline` to the right, lands on a pixel of the right image of that depth (1 cm)."""
            v, u = np.nonzero(np.isfinite(left))
            z = left[v, u]
            x = (u - cx) * z / f - baseline
            ur = np.rint(f * x / z + cx).astype(int)
            inside = (ur >= 0) & (ur < WIDTH)
            return float(np.mean(np.abs(right[v[inside], ur[inside]] - z[inside]) < 0.01))

        true, flipped = agreement(BASELINE), agreement(-BASELINE)
        print('FIGURE: %.3f of the left points agree with the right image (%.3f with the '
              'baseline flipped)' % (true, flipped))
        self.assertGreater(true, 0.95)
        self.assertGreater(true - flipped, 0.02)  # the views differ where the walls slant


if __name__ == '__main__':
    rostest.rosrun('jetbot_rl', 'test_stereo_view', TestStereoView)
