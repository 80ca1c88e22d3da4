"""move_base_msgs/MoveBaseGoal from a planar pose, as mission scripts send them to the move_base
action (the deploy node's, or move_base itself):

    from jetbot_rl.move_base_goal import move_base_goal
    client.send_goal(move_base_goal(1.0, 2.0, yaw=1.57, frame='map'))
"""
import math

import rospy
from move_base_msgs.msg import MoveBaseGoal


def move_base_goal(x, y, yaw=0.0, frame='map', stamp=None):
    """The goal at (x, y) [m] heading `yaw` [rad] in `frame`; `stamp` None: rospy.Time(0) (the
    latest transform, as tf takes it)."""
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = frame
    goal.target_pose.header.stamp = rospy.Time(0) if stamp is None else stamp
    goal.target_pose.pose.position.x = x
    goal.target_pose.pose.position.y = y
    goal.target_pose.pose.orientation.z = math.sin(0.5 * yaw)
    goal.target_pose.pose.orientation.w = math.cos(0.5 * yaw)
    return goal
