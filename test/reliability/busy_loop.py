#!/usr/bin/python3
"""Keeps one core busy until ROS shuts it down (a loaded machine beside the node under test)."""
import rospy

rospy.init_node('busy_loop', anonymous=True)
while not rospy.is_shutdown():
    for _ in range(100000):
        pass
