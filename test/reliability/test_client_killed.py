#!/usr/bin/python3
"""Learners killed (SIGKILL) mid-step: lockstep clients stepping as fast as they can (topic and
~step) and a PPO trainer mid-training. The env node keeps running and stays consistent: the next
~reset answers at once with the newest state, the EnvStep ids it publishes stay consecutive
throughout (+1 per step, unchanged by resets), nothing is rejected; a new trainer resumes from
the last checkpoint and progress.csv's rows carry on with no iteration counted twice. Prints the
slowest ~reset answer after a kill."""
import os
import random
import signal
import tempfile
import time
import unittest

import rospy
import rostest

from jetbot_rl.process_info import node_pid
from jetbot_rl_test.env_client import NODE, EnvClient, wait_for
from jetbot_rl_test.fault_util import (PYTHON, DiagnosticsRecorder, figure, node_command,
                                       package_file, start)
from jetbot_rl_test.ppo_test_util import StatsWatcher, read_csv, run_node

KILLS = 6
MAX_RESET_S = 0.5
STEPS_PER_ITERATION = 16 * 16  # num_steps_per_env x num_envs (client_killed.test)


class TestClientKilled(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.env = EnvClient()  # records every EnvStep the node publishes
        cls.diagnostics = DiagnosticsRecorder(NODE)
        cls.pid = node_pid(NODE)
        cls.reset_seconds = []

    def killed(self, proc, what):
        """Kills `proc` mid-step; checks that the node answers ~reset at once with its newest
        state."""
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        newest = max(m.step for m in self.env.received())
        started = time.monotonic()
        res = self.env.reset_srv(env_ids=[], seed=-1)
        seconds = time.monotonic() - started
        self.reset_seconds.append(seconds)
        self.assertTrue(res.success, res.message)
        self.assertLess(seconds, MAX_RESET_S, what)
        # The newest state: at least the newest EnvStep received before the kill (targets the
        # learner sent just before it died may have been applied since, and their EnvStep may
        # still be on its way), and exactly the state of the last step the node published before
        # the reset's own EnvStep (one connection delivers in order).
        self.assertGreaterEqual(res.state.step, newest, what)

        def reset_index():
            msgs = self.env.received()
            return next((k for k in range(len(msgs) - 1, -1, -1)
                         if msgs[k].step == res.state.step and not any(msgs[k].rewards)), None)
        wait_for(lambda: reset_index() is not None, what='the reset state after ' + what)
        before = self.env.received()[reset_index() - 1]
        self.assertEqual((before.step, any(before.rewards)), (res.state.step, True),
                         '%s: the EnvStep before the reset state' % what)
        return res.state

    def consistent(self):
        """Every EnvStep published so far: ids +1 per step, unchanged by a reset (whose state has
        no rewards); the node's counters agree; nothing rejected."""
        ids = [m.step for m in self.env.received()]
        for k in range(1, len(ids)):
            diff = ids[k] - ids[k - 1]
            msg = self.env.received()[k]
            self.assertIn(diff, (0, 1), 'EnvStep %d after %d' % (ids[k], ids[k - 1]))
            if diff == 0:
                self.assertFalse(any(msg.rewards), 'EnvStep %d twice, not from a reset' % ids[k])
        report = self.diagnostics.next(lambda r: int(r['current step']) == ids[-1],
                                       what='diagnostics at step %d' % ids[-1])
        self.assertEqual(int(report['steps applied']), ids[-1])
        self.assertEqual(int(report['rejected messages']), 0, report['last rejection reason'])
        return ids

    def test_1_clients_killed_mid_step(self):
        rng = random.Random(0)
        for k in range(KILLS):
            count = len(self.env.received())
            proc = start([PYTHON, package_file('test', 'reliability', 'lockstep_client.py'),
                          '__name:=client_%d' % k])
            steps = rng.randint(20, 200)
            try:
                wait_for(lambda: len(self.env.received()) > count + steps,
                         what='client %d to step %d times' % (k, steps))
            except BaseException:
                proc.kill()
                raise
            self.killed(proc, 'client %d killed after %d steps' % (k, steps))
        ids = self.consistent()
        figure('%d lockstep clients killed mid-step: node alive, %d EnvSteps consecutive up to '
               'step %d, nothing rejected; slowest ~reset after a kill %.1f ms'
               % (KILLS, len(ids), ids[-1], max(self.reset_seconds) * 1e3))

    def test_2_trainer_killed_then_resumed(self):
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_trainer_killed_')
        stats = StatsWatcher('/trainer_a/training_stats')
        proc = start(node_command('jetbot_ppo_trainer', 'trainer_a', {
            'env_nodes': NODE, 'iterations': 1000000, 'run_dir': run_dir, 'save_interval': 2}))
        try:
            stats.wait_iteration(5)
            time.sleep(random.Random(1).uniform(0.0, 0.05))  # anywhere in an iteration
        except BaseException:
            proc.kill()
            raise
        self.killed(proc, 'trainer killed mid-training')
        self.assertEqual(node_pid(NODE), self.pid)
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        done = len(rows)  # rows written before the kill: the checkpoint may be older

        code, output = run_node('jetbot_ppo_trainer', 'trainer_b', {
            'env_nodes': NODE, 'iterations': done + 2, 'resume': run_dir, 'save_interval': 2})
        self.assertEqual(code, 0, output)
        line = next(l for l in output.splitlines() if 'resumed from' in l)
        resumed_at = int(line.split('at iteration ')[1].split(',')[0])
        # save_interval 2: the newest checkpoint is at most 2 iterations behind the CSV
        self.assertTrue(done - 2 <= resumed_at <= done, line)
        _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
        self.assertEqual([int(r['iteration']) for r in rows], list(range(1, done + 3)))
        self.assertEqual([int(r['env_steps']) for r in rows],
                         [STEPS_PER_ITERATION * i for i in range(1, done + 3)])
        ids = self.consistent()
        figure('trainer killed after %d iterations: resumed from the checkpoint of iteration %d, '
               'progress.csv iterations 1..%d once each; the node answered ~reset in %.1f ms, '
               'EnvSteps consecutive up to step %d'
               % (done, resumed_at, done + 2, self.reset_seconds[-1] * 1e3, ids[-1]))


if __name__ == '__main__':
    rospy.init_node('test_client_killed')
    rostest.rosrun('jetbot_rl', 'test_client_killed', TestClientKilled)
