#!/usr/bin/python3
"""A lockstep learner for the fault suite: resets jetbot_env once, then steps it as fast as it
can until it is killed, alternating ~wheel_targets (answered on ~env_step) and ~step calls."""
import rospy

from jetbot_rl_test.env_client import EnvClient


def main():
    rospy.init_node('lockstep_client')
    client = EnvClient()
    state = client.reset_srv(env_ids=[], seed=-1).state
    targets = [3.0] * (2 * state.num_envs)  # [rad/s]
    k = 0
    while not rospy.is_shutdown():
        if k % 2:
            state = client.step_topic(state.step, targets)
        else:
            res = client.step_service(state.step, targets)
            if not res.success:
                raise RuntimeError('~step refused: ' + res.message)
            state = res.state
        with client.lock:
            del client.steps[:]  # a client that runs for long keeps no history
        k += 1


if __name__ == '__main__':
    main()
