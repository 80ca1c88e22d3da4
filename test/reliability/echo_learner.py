#!/usr/bin/python3
"""A learner for the fault suite that answers every EnvStep of jetbot_env whose step is below
~steps with WheelTargets for that step (two of them answer every step twice). Publishes ~ready
(latched) once the node has subscribed to its targets and its own subscription is connected, and
~answered (latched): how many answers it has published, raised before each one (an EnvStep lost on
its way to a learner that fell behind is one answer fewer, not an answer lost by the node)."""
import rospy
from std_msgs.msg import Bool, Int64

from jetbot_rl.msg import EnvStep, WheelTargets

NODE = '/jetbot_env'


def main():
    rospy.init_node('echo_learner')
    steps = rospy.get_param('~steps')
    # rospy drops the oldest beyond its queue: one no run fills, so each answer published is sent
    pub = rospy.Publisher(NODE + '/wheel_targets', WheelTargets, queue_size=100000,
                          tcp_nodelay=True)
    ready = rospy.Publisher('~ready', Bool, queue_size=1, latch=True)
    answered = rospy.Publisher('~answered', Int64, queue_size=1, latch=True)
    targets = WheelTargets()
    count = Int64(0)
    answered.publish(count)

    def answer(msg):
        if msg.step < steps:
            count.data += 1
            answered.publish(Int64(count.data))
            targets.step = msg.step
            targets.velocities = [5.0] * (2 * msg.num_envs)  # [rad/s]
            pub.publish(targets)

    sub = rospy.Subscriber(NODE + '/env_step', EnvStep, answer, tcp_nodelay=True)
    # rospy reports neither connection: look again until both are made.
    while not rospy.is_shutdown() and (pub.get_num_connections() == 0 or
                                       sub.get_num_connections() == 0):
        rospy.sleep(0.05)
    ready.publish(Bool(True))
    rospy.spin()


if __name__ == '__main__':
    main()
