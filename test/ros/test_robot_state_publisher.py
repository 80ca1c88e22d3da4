#!/usr/bin/python3
"""joint_states against a real client no one here wrote: Debian's robot_state_publisher, run
unchanged on env_0/joint_states with the same robot_description (tf_prefix env_0, publishing on
/rsp/tf and /rsp/tf_static), gives the same link frames as the node's own tf, at the same stamps,
while the robot drives an arc (the wheels turn at different speeds)."""
import math
import threading
import unittest
import xml.etree.ElementTree as ElementTree

import rospy
import rostest
from tf2_msgs.msg import TFMessage

from jetbot_rl_test.env_client import EventList, wait_for
from jetbot_rl_test.robot_view_client import RobotView, twist

PREFIX = 'env_0/'


def angle_between(a, b):
    """Rotation angle [rad] between two geometry_msgs/Quaternions (normalised first; atan2 keeps
    small angles exact, where acos of the dot product loses them)."""
    na = math.sqrt(a.x ** 2 + a.y ** 2 + a.z ** 2 + a.w ** 2)
    nb = math.sqrt(b.x ** 2 + b.y ** 2 + b.z ** 2 + b.w ** 2)
    # the product conj(a) * b: its vector part is sin(angle / 2), its scalar part cos(angle / 2)
    w = (a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z) / (na * nb)
    x = (a.w * b.x - a.x * b.w - a.y * b.z + a.z * b.y) / (na * nb)
    y = (a.w * b.y + a.x * b.z - a.y * b.w - a.z * b.x) / (na * nb)
    z = (a.w * b.z - a.x * b.y + a.y * b.x - a.z * b.w) / (na * nb)
    return 2.0 * math.atan2(math.sqrt(x * x + y * y + z * z), abs(w))


def distance(a, b):
    return math.sqrt((a.x - b.x) ** 2 + (a.y - b.y) ** 2 + (a.z - b.z) ** 2)


class Frames(object):
    """Every transform received on a tf topic: (child frame, stamp) -> TransformStamped."""

    def __init__(self, topic):
        self.lock = threading.Lock()
        self.transforms = {}
        self.count = EventList()
        self.sub = rospy.Subscriber(topic, TFMessage, self._on_tf, queue_size=1000)

    def _on_tf(self, msg):
        with self.lock:
            for t in msg.transforms:
                self.transforms[(t.child_frame_id, t.header.stamp)] = t
        self.count.append(len(msg.transforms))

    def of(self, child):
        with self.lock:
            return {stamp: t for (c, stamp), t in self.transforms.items() if c == child}


class TestRobotStatePublisher(unittest.TestCase):
    def test_same_frames_as_robot_state_publisher(self):
        urdf = ElementTree.fromstring(rospy.get_param('/robot_description'))
        moving = [j.get('name') for j in urdf.iter('joint') if j.get('type') != 'fixed']
        children = {j.get('name'): j.find('child').get('link') for j in urdf.iter('joint')}
        parents = {j.find('child').get('link'): j.find('parent').get('link')
                   for j in urdf.iter('joint')}
        fixed = [children[j.get('name')] for j in urdf.iter('joint') if j.get('type') == 'fixed']

        node = Frames('/tf')
        rsp = Frames('/rsp/tf')
        rsp_static = Frames('/rsp/tf_static')
        view = RobotView('/' + PREFIX)
        wait_for(lambda: len(rsp.count) > 0 and len(node.count) > 0,
                 what='robot_state_publisher on /rsp/tf and the node on /tf')
        view.drive(twist(0.2, 2.0), 2.0)  # an arc: the wheels turn at different speeds

        # joint_states: every non-fixed joint of the URDF, with position, velocity and effort
        for js in view.joints:
            self.assertEqual(sorted(js.name), sorted(moving))
            self.assertEqual(len(js.position), len(js.name))
            self.assertEqual(len(js.velocity), len(js.name))
            self.assertEqual(len(js.effort), len(js.name))
        self.assertTrue(any(abs(v) > 1.0 for js in view.joints for v in js.velocity))

        # robot_state_publisher stamps its transforms with the joint state's stamp, the node its
        # tf with the state's simulation time: the same steps carry the same stamps
        for joint in moving:
            child = children[joint]
            ours = node.of(PREFIX + child)
            theirs = rsp.of(PREFIX + child)
            matched = 0
            worst_distance = worst_angle = 0.0
            for stamp, t in theirs.items():
                mine = ours.get(stamp)
                if mine is None:
                    continue
                matched += 1
                self.assertEqual(t.header.frame_id, PREFIX + parents[child])
                self.assertEqual(mine.header.frame_id, t.header.frame_id)
                worst_distance = max(worst_distance, distance(
                    mine.transform.translation, t.transform.translation))
                worst_angle = max(worst_angle, angle_between(
                    mine.transform.rotation, t.transform.rotation))

            print('%s: %d transforms matched at the same stamps; largest differences %.2g m, '
                  '%.2g rad' % (child, matched, worst_distance, worst_angle))
            self.assertGreater(matched, 20, 'too few transforms of %s at matching stamps' % child)
            self.assertLess(worst_distance, 1e-6, child)
            self.assertLess(worst_angle, 1e-5, child)
            # and the wheel turned while they were compared
            angles = [angle_between(t.transform.rotation, theirs[min(theirs)].transform.rotation)
                      for t in theirs.values()]
            self.assertGreater(max(angles), 1.0, '%s did not turn' % child)

        # fixed links: robot_state_publisher's static transforms
        wait_for(lambda: all(rsp_static.of(PREFIX + link) for link in fixed),
                 what='robot_state_publisher\'s static transforms')
        for link in fixed:
            static = list(rsp_static.of(PREFIX + link).values())[0]
            mine = list(node.of(PREFIX + link).values())[-1]
            self.assertEqual(mine.header.frame_id, static.header.frame_id)
            self.assertLess(distance(mine.transform.translation, static.transform.translation),
                            1e-6, link)
            self.assertLess(angle_between(mine.transform.rotation, static.transform.rotation),
                            1e-5, link)


if __name__ == '__main__':
    rospy.init_node('test_robot_state_publisher')
    rostest.rosrun('jetbot_rl', 'test_robot_state_publisher', TestRobotStatePublisher)
