#!/usr/bin/python3
"""A short command-task training through train.launch: the reward per step rises far above the
random policy's first iteration and, late in the episodes, the robots face their commands and
drive along them (progress.csv's obs_mean_* columns); then the shipped command policy
(policies/command), played in lockstep mode with commands set through ~set_command (held across
resets), turns to each command and drives along it."""
import math
import os
import threading
import unittest

import rospkg
import rospy
import rostest

from jetbot_rl.msg import EnvStep
from jetbot_rl.srv import SetCommand
from jetbot_rl_test.ppo_test_util import REQUIRED_HEADER, TIMEOUT, StatsWatcher, read_csv, run_node

DOT = 'obs_mean_forward_dot_command'
VX = 'obs_mean_lin_vel_b_x'
MAX_SPEED = 0.6           # m/s: 20 rad/s x 0.03 m
FIRST_REWARD_MAX = 0.3    # m/s: a random policy's reward per step (about -0.1 to 0.2)
LATE_STEP = 149           # second half of an episode (as the trainer's obs_mean_* columns)
LAST_STEP = 298           # observation of an episode's last step (time-out after 299 steps)
PLAY_ENVS = 8             # envs 0..7 get the commands at 22.5 + 45 k degrees
PLAY_STEPS = 700          # two episodes of 299 steps and a bit
SHIPPED = os.path.join(rospkg.RosPack().get_path('jetbot_rl'), 'policies', 'command')


class TestTrainCommand(unittest.TestCase):
    def test_train_then_play_shipped(self):
        run_dir = rospy.get_param('~run_dir')
        iterations = rospy.get_param('~iterations')
        stats = StatsWatcher('/jetbot_ppo_trainer/training_stats')
        last = stats.wait_iteration(iterations, timeout=180.0)
        self.assertIn(DOT, last)

        header, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertTrue(header.startswith(REQUIRED_HEADER), header)
        for column in (DOT, VX, 'obs_mean_forward_cross_command_z', 'obs_samples'):
            self.assertIn(column, header.split(','))
        self.assertEqual([int(r['iteration']) for r in rows], list(range(1, iterations + 1)))
        first = rows[0]['mean_reward_per_step']
        self.assertLess(first, FIRST_REWARD_MAX, 'the first iteration is not random-like')
        tail = [r for r in rows[-5:] if not math.isnan(r[DOT])]
        self.assertTrue(tail, 'no late-episode samples in the last 5 iterations')
        reward = sum(r['mean_reward_per_step'] for r in rows[-5:]) / len(rows[-5:])
        dot = sum(r[DOT] for r in tail) / len(tail)
        vx = sum(r[VX] for r in tail) / len(tail)
        summary = ('last 5 iterations: reward/step %.3f (first %.3f), late-episode mean dot %.3f, '
                   'v_x %.3f m/s' % (reward, first, dot, vx))
        rospy.loginfo(summary)
        # Random policy: reward/step about 0, late dot about 0 (uniform commands), v_x about 0.
        self.assertGreater(reward, first + 0.8, summary)
        self.assertGreater(reward, 1.0, summary)
        self.assertGreater(dot, 0.8, summary)
        self.assertGreater(vx, 0.5 * MAX_SPEED, summary)

        # --- play the shipped policy: known commands (held across resets) for envs 0..7 ---
        rospy.wait_for_service('/jetbot_env/set_command', timeout=TIMEOUT)
        set_command = rospy.ServiceProxy('/jetbot_env/set_command', SetCommand)
        commands = []
        for e in range(PLAY_ENVS):
            angle = math.radians(22.5 + 45.0 * e)
            commands.append((math.cos(angle), math.sin(angle)))
            response = set_command(env_id=e, x=commands[-1][0], y=commands[-1][1], hold=True)
            self.assertTrue(response.success, response.message)

        # Per env: the episodes as lists of (episode step, dot, v_x), in order.
        episodes = [[] for _ in range(PLAY_ENVS)]
        lock = threading.Lock()

        def on_step(msg):
            d = msg.obs_dim
            with lock:
                for e in range(PLAY_ENVS):
                    k = msg.episode_steps[e]
                    o = msg.observations[e * d:(e + 1) * d]
                    if k == 0 or not episodes[e]:
                        episodes[e].append([])
                    episodes[e][-1].append((k, o[0], o[2]))
        sub = rospy.Subscriber('/jetbot_env/env_step', EnvStep, on_step, queue_size=1000,
                               tcp_nodelay=True)
        code, output = run_node('jetbot_policy_node', 'jetbot_policy', {
            'checkpoint': SHIPPED,
            'mode': 'lockstep', 'steps': PLAY_STEPS, 'reset_seed': 1}, timeout=TIMEOUT)
        sub.unregister()
        self.assertEqual(code, 0, output)
        self.assertIn('drove %d steps' % PLAY_STEPS, output)
        with lock:
            played = [[list(ep) for ep in env] for env in episodes]
        report, failures = [], []
        for e in range(PLAY_ENVS):
            # Whole episodes only (the last one is cut by the end of play).
            whole = [ep for ep in played[e] if ep and ep[0][0] == 0 and ep[-1][0] >= LAST_STEP]
            if len(whole) < 2:
                failures.append('env %d: %d whole episodes seen' % (e, len(whole)))
                continue
            for ep in whole:
                late = [s for s in ep if s[0] >= LATE_STEP]
                mean_dot = sum(s[1] for s in late) / len(late)
                mean_vx = sum(s[2] for s in late) / len(late)
                # First episode step from which the robot faces the command for good.
                facing = next((ep[i][0] for i in range(len(ep))
                               if all(s[1] > 0.9 for s in ep[i:])), None)
                line = ('env %d command (%5.2f, %5.2f): start dot %5.2f, dot > 0.9 from step %s, '
                        'steps >= %d: mean dot %.3f, mean v_x %.3f m/s'
                        % (e, commands[e][0], commands[e][1], ep[0][1], facing, LATE_STEP,
                           mean_dot, mean_vx))
                report.append(line)
                if mean_dot <= 0.9 or mean_vx <= 0.5 * MAX_SPEED:
                    failures.append(line)
        text = '\n'.join(report)
        rospy.loginfo('played:\n%s', text)
        self.assertFalse(failures, '\n'.join(failures) + '\nall:\n' + text)
        # The robots started facing elsewhere (every episode starts facing world +x): they had
        # to turn.
        self.assertTrue(any(ep[0][1] < 0.0 for env in played for ep in env if ep[0][0] == 0))


if __name__ == '__main__':
    rospy.init_node('test_train_command')
    rostest.rosrun('jetbot_rl', 'test_train_command', TestTrainCommand)
