"""Test helpers for launch/world_view.launch (world_view.test, gazebo_world.test)."""
import math

import rospy
import tf2_ros

TIMEOUT = 30.0
# Wider than either robot (the tribot: wheels 0.018 m wide with their centres 0.160 m apart, 0.178 m
# across; the Jetbot is narrower): robots nearer than this overlap in RViz.
ROBOT_WIDTH = 0.2


def start_apart(test):
    """The Jetbot and the tribot of world_view.launch, each in its own env node, are more than a
    robot's width apart in the world frame RViz shows them in (both envs' origins are the
    world's), so that neither hides the other."""
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    positions = [buffer.lookup_transform('world', frame, rospy.Time(0),
                                         rospy.Duration(TIMEOUT)).transform.translation
                 for frame in ('jetbot/env_0/base_link', 'tribot/env_0/base_footprint')]
    apart = math.hypot(positions[0].x - positions[1].x, positions[0].y - positions[1].y)
    print('FIGURE: world_view: the Jetbot at (%.2f, %.2f), the tribot at (%.2f, %.2f): %.2f m apart'
          % (positions[0].x, positions[0].y, positions[1].x, positions[1].y, apart))
    test.assertGreater(apart, ROBOT_WIDTH)
