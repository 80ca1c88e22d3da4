#!/usr/bin/python3
"""SIGINT and SIGTERM end every node within 2 s with exit status 0, having saved what it must:
jetbot_env (stepping in realtime mode, markers on) sends its DELETEALL markers, which a
subscriber receives after the last marker array; jetbot_ppo_trainer (mid-training) writes
checkpoints/latest.pt and summary.yaml with status interrupted; jetbot_policy_node (driving in
lockstep) stops; jetbot_rl_manager with the env as a nodelet unloads it (its DELETEALL leaves)
and exits. Prints each node's time from the signal to its exit."""
import os
import signal
import tempfile
import unittest

import rospy
import rostest
from visualization_msgs.msg import Marker, MarkerArray

from jetbot_rl.msg import EnvStep
from jetbot_rl_test.env_client import EventList, wait_for
from jetbot_rl_test.fault_util import figure, node_command, signal_and_wait, start, stop_all
from jetbot_rl_test.ppo_test_util import StatsWatcher, read_csv

MAX_EXIT_S = 2.0
SIGNALS = (signal.SIGINT, signal.SIGTERM)


def deleteall(array):
    return any(m.action == Marker.DELETEALL for m in array.markers)


class TestSignals(unittest.TestCase):
    run_dir = None  # a checkpoint for the player, written by the trainer test

    def exits_cleanly(self, what, proc, sig):
        """Signals `proc`; checks exit status 0 within MAX_EXIT_S; returns the output."""
        seconds, code, output = signal_and_wait(proc, sig)
        figure('%s %s: exit status %d after %.2f s' % (what, sig.name, code, seconds))
        self.assertEqual(code, 0, '%s after %s:\n%s' % (what, sig.name, output))
        self.assertLess(seconds, MAX_EXIT_S, '%s after %s:\n%s' % (what, sig.name, output))
        return output

    def test_1_env_node_sends_deleteall_and_exits(self):
        for sig in SIGNALS:
            with self.subTest(signal=sig.name):
                self.env_node_sends_deleteall_and_exits(sig)

    def env_node_sends_deleteall_and_exits(self, sig):
        name = 'signal_env_' + sig.name.lower()
        arrays = EventList()
        sub = rospy.Subscriber('/%s/markers' % name, MarkerArray, arrays.append)
        # realtime, 10x: it steps (and sends markers) on its own at 600 Hz while signalled
        proc = start(node_command('jetbot_env_node', name, {
            'num_envs': 4, 'tf_envs': 2, 'mode': 'realtime', 'real_time_factor': 10.0,
            'num_threads': 1, 'publish_clock': 'false'}))
        try:
            # the latched start-up array, then at least one sent while stepping
            wait_for(lambda: len(arrays) >= 2, what='markers of /' + name)
            self.assertFalse(deleteall(arrays[0]))
        except BaseException:
            proc.kill()
            raise
        try:
            self.exits_cleanly('jetbot_env', proc, sig)
            # Sent before the exit, the DELETEALL may still be on its way to our callback.
            wait_for(lambda: deleteall(arrays[-1]), timeout=10.0,
                     what='DELETEALL as the last marker array of /%s after %s (got %d arrays, '
                     'none with DELETEALL)' % (name, sig.name, len(arrays)))
            figure('jetbot_env %s: DELETEALL received after %d marker arrays'
                   % (sig.name, len(arrays) - 1))
        finally:
            sub.unregister()

    def test_2_trainer_saves_and_exits(self):
        for sig in SIGNALS:
            name = 'signal_trainer_' + sig.name.lower()
            run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_signals_')
            stats = StatsWatcher('/%s/training_stats' % name)
            proc = start(node_command('jetbot_ppo_trainer', name, {
                'env_nodes': '/jetbot_env', 'iterations': 1000000, 'run_dir': run_dir,
                'save_interval': 1000}))
            try:
                stats.wait_iteration(2)
            except BaseException:
                proc.kill()
                raise
            output = self.exits_cleanly('jetbot_ppo_trainer', proc, sig)
            self.assertIn('status: interrupted', output)
            self.assertTrue(os.path.isfile(os.path.join(run_dir, 'checkpoints/latest.pt')))
            _, rows = read_csv(os.path.join(run_dir, 'progress.csv'))
            with open(os.path.join(run_dir, 'summary.yaml')) as f:
                summary = f.read()
            self.assertIn('status: interrupted', summary)
            self.assertIn('iterations: %d\n' % len(rows), summary)
            figure('jetbot_ppo_trainer %s: checkpoint and summary saved at iteration %d'
                   % (sig.name, len(rows)))
            TestSignals.run_dir = run_dir

    def test_3_policy_node_exits(self):
        self.assertIsNotNone(self.run_dir, 'needs the trainer test\'s checkpoint')
        checkpoint = os.path.join(self.run_dir, 'checkpoints/latest.pt')
        steps = EventList()
        sub = rospy.Subscriber('/jetbot_env/env_step', EnvStep, lambda m: steps.append(m.step))
        for sig in SIGNALS:
            name = 'signal_policy_' + sig.name.lower()
            count = len(steps)
            proc = start(node_command('jetbot_policy_node', name, {
                'env_nodes': '/jetbot_env', 'checkpoint': checkpoint, 'mode': 'lockstep'}))
            try:
                wait_for(lambda: len(steps) > count + 50, what=name + ' to drive 50 steps')
            except BaseException:
                proc.kill()
                raise
            self.exits_cleanly('jetbot_policy_node', proc, sig)
        sub.unregister()

    def test_4_nodelet_manager_unloads_and_exits(self):
        """jetbot_rl_manager with the env as a nodelet (stepping in realtime, markers on): the
        env's DELETEALL leaves before the manager exits 0."""
        for sig in SIGNALS:
            with self.subTest(signal=sig.name):
                manager = 'signal_manager_' + sig.name.lower()
                name = 'signal_env_nodelet_' + sig.name.lower()
                arrays = EventList()
                sub = rospy.Subscriber('/%s/markers' % name, MarkerArray, arrays.append)
                proc = start(['rosrun', 'jetbot_rl', 'jetbot_rl_manager', '__name:=' + manager])
                # The loader's private parameters become the nodelet's (same name).
                loader = start(['rosrun', 'nodelet', 'nodelet', 'load', 'jetbot_rl/EnvNodelet',
                                '/' + manager, '--no-bond', '__name:=' + name, '_num_envs:=4',
                                '_tf_envs:=2', '_mode:=realtime', '_real_time_factor:=10.0',
                                '_num_threads:=1', '_publish_clock:=false'])
                try:
                    wait_for(lambda: len(arrays) >= 2, what='markers of the nodelet /' + name)
                    self.exits_cleanly('jetbot_rl_manager', proc, sig)
                    wait_for(lambda: deleteall(arrays[-1]), timeout=10.0,
                             what='DELETEALL as the last marker array of /%s after %s'
                             % (name, sig.name))
                    figure('jetbot_rl_manager %s: the env nodelet\'s DELETEALL received after %d '
                           'marker arrays' % (sig.name, len(arrays) - 1))
                finally:
                    sub.unregister()
                    loader.send_signal(signal.SIGINT)  # its manager is gone: it just ends
                    stop_all(proc)
                    try:
                        loader.communicate(timeout=10)
                    finally:
                        stop_all(loader)


if __name__ == '__main__':
    rospy.init_node('test_signals')
    rostest.rosrun('jetbot_rl', 'test_signals', TestSignals)
