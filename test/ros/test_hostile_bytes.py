#!/usr/bin/python3
"""Hand-made TCPROS bytes whose array and string lengths lie, sent to jetbot_env through its topic
(a fake publisher registered with the master) and its services (a raw client), for every array
and string field: each is refused unread and counted in /diagnostics, the node's peak resident set
grows by less than 50 MB, a normal ~step sent while the lie is in flight is answered within 0.5 s
and the state goes on as if nothing had arrived; a cut SetCommand request and a cut cmd_vel Twist
likewise. Also: a rospy numpy_msg subscriber (the Python learner side) fed lying EnvSteps drops
them without growing, and a training jetbot_ppo_trainer refuses them, counts them on
/diagnostics and trains on."""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Twist
from rospy.numpy_msg import numpy_msg

from jetbot_rl.msg import EnvStep, WheelTargets
from jetbot_rl.process_info import node_pid, peak_rss_kb, start_peak_rss
from jetbot_rl.srv import (GetRandomization, GetRandomizationRequest, Reset, ResetRequest,
                           SetCommand, SetCommandRequest, Step, StepRequest)
from jetbot_rl_test.env_client import NODE, EventList, EnvClient, notify, wait_for
from jetbot_rl_test.raw_tcpros import FakePublisher, RawServiceClient, lying_length, serialize

GOOD = [5.0, 4.0, -3.0, 6.0]  # 2 envs x 2 wheels [rad/s]
MAX_RSS_GROWTH_KB = 50 * 1024
MAX_ANSWER_S = 0.5


CMD_VEL = 'env_0/cmd_vel'  # env 0's robot view (robot_view_envs 1), relative to the node's namespace


def say(text):
    """Figures for the test output (rostest keeps the test's stdout), as docs/reliability.md
    quotes them."""
    sys.stdout.write('FIGURE: ' + text + '\n')
    sys.stdout.flush()


def targets(step, frame_id='base'):
    msg = WheelTargets()
    msg.header.frame_id = frame_id
    msg.step = step
    msg.velocities = list(GOOD)
    return msg


def append_char(field):
    """grow() for a string field given as a path of attribute names."""
    def grow(msg):
        *parents, name = field.split('.')
        for p in parents:
            msg = getattr(msg, p)
        setattr(msg, name, getattr(msg, name) + 'x')
    return grow


def append_item(field, item):
    def grow(msg):
        *parents, name = field.split('.')
        for p in parents:
            msg = getattr(msg, p)
        setattr(msg, name, list(getattr(msg, name)) + [item])
    return grow


def lies():
    """Lying lengths to try; None: one element more than the bytes left."""
    return list(rospy.get_param('~lies', [2 ** 31, 2 ** 32 - 1])) + [None]


class TestHostileBytes(unittest.TestCase):
    def test_env_node_refuses_lying_lengths(self):
        env = EnvClient()
        pid = node_pid(NODE)
        state = env.reset_srv(env_ids=[], seed=-1).state
        for _ in range(3):
            state = env.step_topic(state.step, GOOD)
        fakes = {
            'wheel_targets': FakePublisher(NODE + '/wheel_targets', WheelTargets,
                                           on_connect=notify),
            CMD_VEL: FakePublisher('/' + CMD_VEL, Twist, caller_id='/raw_cmd_vel_publisher',
                                   on_connect=notify),
        }
        raw = {
            'step': RawServiceClient(NODE + '/step', Step),
            'reset': RawServiceClient(NODE + '/reset', Reset),
            'set_command': RawServiceClient(NODE + '/set_command', SetCommand),
            'get_randomization': RawServiceClient(NODE + '/get_randomization', GetRandomization),
        }
        wait_for(lambda: all(f.connected(NODE) > 0 for f in fakes.values()),
                 what='jetbot_env to connect to the fake publishers')

        def reset_request():
            return ResetRequest(env_ids=[0, 1], seed=3, episode_steps=[5, 7])

        # (channel, field as the reason names it, element size [bytes], grow, sample request)
        cases = [
            ('wheel_targets', 'header.frame_id', 1, append_char('header.frame_id'), None),
            ('wheel_targets', 'velocities', 4, append_item('velocities', 1.0), None),
            ('step', 'actions.header.frame_id', 1, append_char('actions.header.frame_id'), None),
            ('step', 'actions.velocities', 4, append_item('actions.velocities', 1.0), None),
            ('reset', 'env_ids', 4, append_item('env_ids', 0), reset_request),
            ('reset', 'episode_steps', 4, append_item('episode_steps', 0), reset_request),
            ('get_randomization', 'env_ids', 4, append_item('env_ids', 0),
             lambda: GetRandomizationRequest(env_ids=[0, 1])),
        ]
        attacks = [(c, lie) for c in cases for lie in lies()]
        # SetCommand and Twist have no array or string: one cut short is refused the same way.
        attacks.append((('set_command', 'hold', 1, None,
                         lambda: SetCommandRequest(env_id=0, x=1.0, y=0.0, hold=True)), 'cut'))
        attacks.append(((CMD_VEL, 'angular.z', 8, None, Twist), 'cut'))

        figures = []
        malformed = 0
        try:
            for (channel, field, size, grow, sample), lie in attacks:
                s = state.step
                if sample is None:  # the targets (or ~step request) for the current step
                    sample = (lambda: StepRequest(actions=targets(s))) if channel == 'step' \
                        else (lambda: targets(s))
                if lie == 'cut':
                    payload, length = serialize(sample())[:-1], 'cut'
                else:
                    payload, length = lying_length(sample(), grow, size, lie)
                what = '%s %s length %s' % (channel, field, length)
                rss_before = start_peak_rss(pid)
                # The lie, then at once a normal ~step from another connection: it must not wait
                # for the node to chew on the lie.
                if channel in fakes:
                    fakes[channel].send(payload)
                else:
                    raw[channel].send(payload)
                started = time.monotonic()
                res = env.step_service(s, GOOD)
                answer_s = time.monotonic() - started
                if channel not in fakes:
                    ok, error = raw[channel].receive()
                    self.assertFalse(ok, what + ' was answered as valid')
                    self.assertTrue(error.startswith(field + ': '), '%s: %s' % (what, error))
                malformed += 1
                status = env.wait_diagnostics(
                    lambda d: int(d.get('malformed messages', -1)) >= malformed,
                    'diagnostics counting %d malformed messages' % malformed)
                growth_kb = peak_rss_kb(pid) - rss_before  # the lie has been handled
                figures.append((what, growth_kb, answer_s))
                say('%-50s peak RSS growth %7d kB, normal ~step answered in %6.1f ms'
                    % (what, growth_kb, answer_s * 1e3))
                self.assertLess(growth_kb, MAX_RSS_GROWTH_KB, what)
                self.assertLess(answer_s, MAX_ANSWER_S, what)
                # the lie changed nothing: the step counter and the episodes went on from s
                self.assertTrue(res.success, '%s: %s' % (what, res.message))
                self.assertEqual(res.state.step, s + 1, what)
                self.assertEqual(list(res.state.episode_steps),
                                 [e + 1 for e in state.episode_steps], what + ' reset envs')
                state = res.state
                self.assertEqual(int(status['malformed messages']), malformed, what)
                self.assertTrue(status['last malformed reason'].startswith(
                    '%s refused unread: %s: ' % (channel, field)), status['last malformed reason'])
                self.assertGreaterEqual(int(status['rejected messages']), malformed)
        finally:
            for f in fakes.values():
                f.close()
            for client in raw.values():
                client.close()
            if figures:
                say('%d lying messages: largest peak RSS growth %d kB, slowest normal ~step '
                    '%.1f ms' % (len(figures), max(f[1] for f in figures),
                                 max(f[2] for f in figures) * 1e3))

    def test_rospy_subscriber_drops_lying_env_step(self):
        """rospy's generated deserializers slice the received bytes: a lying EnvStep costs no
        memory. rospy logs the error and drops the connection it came on for good (its reconnect
        reads the handshake from a buffer still holding the lie); the others carry on."""
        topic = '/hostile_bytes/env_step'
        me = rospy.get_name()
        received = EventList()
        # numpy_msg: the deserialiser JetbotVecEnv subscribes with (src/jetbot_rl/node_link.py)
        sub = rospy.Subscriber(topic, numpy_msg(EnvStep), received.append)
        honest = FakePublisher(topic, EnvStep, caller_id='/raw_honest_publisher',
                               on_connect=notify)

        def sample(step):
            msg = EnvStep(step=step, num_envs=2, obs_dim=3, observations=[1.0] * 6,
                          rewards=[0.5, 0.5], terminated=[0, 1], truncated=[1, 0],
                          episode_steps=[3, 0], reset_env_ids=[1], final_observations=[2.0] * 3)
            msg.header.frame_id = 'world'
            return msg
        fields = [('header.frame_id', 1, append_char('header.frame_id')),
                  ('observations', 4, append_item('observations', 0.0)),
                  ('rewards', 4, append_item('rewards', 0.0)),
                  ('terminated', 1, append_item('terminated', 0)),
                  ('truncated', 1, append_item('truncated', 0)),
                  ('episode_steps', 4, append_item('episode_steps', 0)),
                  ('reset_env_ids', 4, append_item('reset_env_ids', 0)),
                  ('final_observations', 4, append_item('final_observations', 0.0))]
        wait_for(lambda: honest.connected(me) > 0, what='our subscriber to connect')
        rss_before = start_peak_rss(os.getpid())
        step = 0
        try:
            for field, size, grow in fields:
                for lie in lies():
                    payload, length = lying_length(sample(0), grow, size, lie)
                    what = '%s length %s' % (field, length)
                    hostile = FakePublisher(topic, EnvStep, caller_id='/raw_hostile_publisher',
                                            on_connect=notify)
                    try:
                        wait_for(lambda: hostile.connected(me) > 0,
                                 what='our subscriber to connect to the hostile publisher')
                        hostile.send(payload)
                        self.assertTrue(hostile.wait_until_dropped(me, 30.0),
                                        'rospy kept the connection after ' + what)
                    finally:
                        hostile.close()
                    step += 1
                    honest.send(serialize(sample(step)))
                    wait_for(lambda: received and received[-1].step == step,
                             what='the honest EnvStep after ' + what)
            growth_kb = peak_rss_kb(os.getpid()) - rss_before
            say('rospy subscriber: %d lying EnvSteps dropped, peak RSS growth %d kB'
                % (step, growth_kb))
            self.assertLess(growth_kb, MAX_RSS_GROWTH_KB)
            self.assertEqual([m.step for m in received], list(range(1, step + 1)))
        finally:
            sub.unregister()
            honest.close()

    def test_trainer_refuses_lying_env_steps(self):
        """The C++ learner side (RosVecEnv in jetbot_ppo_trainer) training against the node:
        lying EnvSteps from a fake publisher on the node's ~env_step are refused unread, counted
        on /diagnostics, cost no memory, and training goes on until SIGINT ends it cleanly."""
        name = '/hostile_trainer'
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_hostile_trainer_')
        counts = EventList()

        def on_diagnostics(msg):
            for status in msg.status:
                if status.name == name + ': env client ' + NODE:
                    counts.append({kv.key: kv.value for kv in status.values})
        diag_sub = rospy.Subscriber('/diagnostics', DiagnosticArray, on_diagnostics)
        proc = subprocess.Popen(['rosrun', 'jetbot_rl', 'jetbot_ppo_trainer',
                                 '__name:=' + name[1:], '_env_nodes:=' + NODE,
                                 '_iterations:=1000000', '_run_dir:=' + run_dir],
                                stdout=subprocess.DEVNULL)
        sent = 0
        try:
            wait_for(lambda: os.path.exists(os.path.join(run_dir, 'progress.csv')),
                     what='the trainer to train', recheck=0.1)
            pid = node_pid(name)
            rss_before = start_peak_rss(pid)
            sample = EnvStep(step=1, num_envs=2, obs_dim=3, observations=[1.0] * 6,
                             rewards=[0.5, 0.5], terminated=[0, 0], truncated=[0, 0],
                             episode_steps=[3, 3])
            for field, size, grow in [('header.frame_id', 1, append_char('header.frame_id')),
                                      ('observations', 4, append_item('observations', 0.0)),
                                      ('episode_steps', 4, append_item('episode_steps', 0))]:
                for lie in lies():
                    payload, _ = lying_length(sample, grow, size, lie)
                    fake = FakePublisher(NODE + '/env_step', EnvStep,
                                         caller_id='/raw_env_step_publisher', on_connect=notify)
                    try:
                        wait_for(lambda: fake.connected(name) > 0,
                                 what='the trainer to connect to the fake publisher')
                        fake.send(payload)
                        sent += 1
                        wait_for(lambda: counts and
                                 int(counts[-1]['malformed messages']) == sent,
                                 what='/diagnostics counting %d malformed EnvSteps' % sent)
                    finally:
                        fake.close()
            growth_kb = peak_rss_kb(pid) - rss_before
            self.assertIn('refused unread: ', counts[-1]['last reason'])
            say('trainer: %d lying EnvSteps refused unread, peak RSS growth %d kB'
                % (sent, growth_kb))
            self.assertLess(growth_kb, MAX_RSS_GROWTH_KB)
        finally:
            diag_sub.unregister()
            proc.send_signal(signal.SIGINT)
            code = proc.wait(timeout=30)
        self.assertEqual(code, 0)
        with open(os.path.join(run_dir, 'summary.yaml')) as f:
            self.assertIn('status: interrupted', f.read())


if __name__ == '__main__':
    rospy.init_node('test_hostile_bytes')
    rostest.rosrun('jetbot_rl', 'test_hostile_bytes', TestHostileBytes)
