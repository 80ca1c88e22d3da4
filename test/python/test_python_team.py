#!/usr/bin/python3
"""Several robots per env (robots_per_env) through a jetbot_env node and JetbotVecEnv: 2 envs of
20 robots (config/navigation_swap.yaml) are 40 rows, robot k of env e at row 20 e + k; robots
that all drive straight for the circle's centre hit each other, and those episodes end as
OUTCOME_COLLISION_ROBOT in both envs; in rounds (the file's rounds: true) a robot that ended
waits until all have, and then ends a wait (OUTCOME_WAITED) with the others' new start; each
robot's odom is under env_<e>/robot_<k>/ (in the node's namespace, as every robot view
topic)."""
import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import Odometry

from jetbot_rl import JetbotVecEnv
from jetbot_rl.msg import EnvStep
from jetbot_rl_test.env_client import UNREPORTED_RECHECK, wait_for
from jetbot_rl_test.py_test_util import EventList

NODE = '/jetbot_env'
ENVS, ROBOTS = 2, 20
RADIUS = 3.0  # swap_radius of config/navigation_swap.yaml [m]


class TestTeam(unittest.TestCase):
    def test_rows_are_robots_and_they_hit_each_other(self):
        odom = {}
        subs = []
        for row in (0, 1, 20, 21):
            name = 'env_%d/robot_%d/' % (row // ROBOTS, row % ROBOTS)
            odom[row] = EventList()
            subs.append(rospy.Subscriber('/' + name + 'odom', Odometry, odom[row].append,
                                         tcp_nodelay=True))
        for s in subs:  # connected before the steps whose odom they should see
            wait_for(lambda s=s: s.get_num_connections() > 0, what=s.name + ' to connect',
                     recheck=UNREPORTED_RECHECK)
        with JetbotVecEnv(NODE, timeout=30.0) as env:
            self.assertEqual(env.num_envs, ENVS * ROBOTS)
            obs, _ = env.reset(seed=4)
            self.assertEqual(obs.shape, (ENVS * ROBOTS, len(env.observation_names)))
            # Straight ahead at full speed: every robot starts facing the centre (+-0.5 rad).
            ahead = np.tile([env.action_high[0], 0.0], (env.num_envs, 1)).astype(np.float32)
            hits = np.zeros(env.num_envs, dtype=bool)
            waits = np.zeros(env.num_envs, dtype=bool)
            # Until both envs saw a robot collision and a round's end (600 steps: a time-out).
            for _ in range(700):
                if (hits[:ROBOTS].any() and hits[ROBOTS:].any() and waits[:ROBOTS].any()
                        and waits[ROBOTS:].any()):
                    break
                obs, rewards, terminated, truncated, infos = env.step(ahead)
                self.assertEqual(rewards.shape, (ENVS * ROBOTS,))
                if '_outcome' in infos:
                    ended = infos['_outcome']
                    outcome = infos['outcome'][ended]
                    self.assertTrue(set(outcome.tolist()) <= {0, 1, 2, 4, 5}, outcome)
                    hits |= ended & (infos['outcome'] == EnvStep.OUTCOME_COLLISION_ROBOT)
                    waited = ended & (infos['outcome'] == EnvStep.OUTCOME_WAITED)
                    # A wait ends only with a new round: every robot of its env starts anew.
                    for e in range(ENVS):
                        rows = slice(e * ROBOTS, (e + 1) * ROBOTS)
                        if waited[rows].any():
                            self.assertTrue(np.all(infos['episode_steps'][rows] == 0),
                                            infos['episode_steps'][rows])
                    waits |= waited
            self.assertTrue(hits[:ROBOTS].any() and hits[ROBOTS:].any(), hits)
            self.assertTrue(waits[:ROBOTS].any() and waits[ROBOTS:].any(), waits)
        for row, messages in odom.items():
            messages.wait_for(lambda m=messages: len(m) > 0, 'odom of row %d' % row, 30.0)
            msg = messages[0]
            prefix = 'env_%d/robot_%d/' % (row // ROBOTS, row % ROBOTS)
            self.assertEqual(msg.header.frame_id, prefix + 'odom')
            self.assertTrue(msg.child_frame_id.startswith(prefix), msg.child_frame_id)
        # Two robots of one env are two robots: apart, each within the circle.
        for a, b in ((0, 1), (20, 21)):
            pa, pb = (odom[r][-1].pose.pose.position for r in (a, b))
            self.assertGreater(np.hypot(pa.x - pb.x, pa.y - pb.y), 0.1)
            self.assertLess(np.hypot(pa.x, pa.y), RADIUS + 0.5)
        for s in subs:
            s.unregister()


if __name__ == '__main__':
    rospy.init_node('test_python_team', disable_signals=True)
    rostest.rosrun('jetbot_rl', 'test_python_team', TestTeam)
