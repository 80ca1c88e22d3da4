#!/usr/bin/python3
"""Training over several hosts of one ROS graph, on one machine: the test makes three hosts in
network namespaces (a bridge on host a, a veth pair to each of hosts b and c, one /24 inside the
namespaces only), runs the master and the trainer on a and an env node on each of b and c
(env_host.launch, ROS_MASTER_URI and ROS_IP per host, as docs/training.md's multi-host set-up says),
and checks that the training reaches the velocity target. The namespaces and every process are
removed whatever happens."""
import os
import random
import re
import signal
import subprocess
import tempfile
import time
import unittest

import rospy
import rostest

NODES = '[jetbot_env_0, jetbot_env_1]'
TARGET = 0.54  # m/s
TIMEOUT = 300.0


def sh(*args):
    subprocess.run(args, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


class Hosts(object):
    """Three network namespaces <prefix>_a (with the bridge), _b and _c on 10.213.X.0/24."""

    def __init__(self):
        self.prefix = 'jrtest%d' % os.getpid()
        subnet = random.randint(1, 250)
        self.address = {h: '10.213.%d.%d' % (subnet, i + 1) for i, h in enumerate('abc')}
        self.names = {h: '%s_%s' % (self.prefix, h) for h in 'abc'}
        self.processes = []
        self.remove_stale()
        try:
            self.connect()
        except BaseException:
            self.remove_namespaces()  # a set-up that fails half-way leaves nothing behind
            raise

    def connect(self):
        for h in 'abc':
            sh('ip', 'netns', 'add', self.names[h])
            self.run(h, 'ip', 'link', 'set', 'lo', 'up')
        a = self.names['a']
        self.run('a', 'ip', 'link', 'add', 'br0', 'type', 'bridge')
        self.run('a', 'ip', 'addr', 'add', self.address['a'] + '/24', 'dev', 'br0')
        self.run('a', 'ip', 'link', 'set', 'br0', 'up')
        for h in 'bc':
            outside, inside = 'v%s%s' % (self.prefix[-6:], h), 'eth0'
            sh('ip', 'link', 'add', outside, 'netns', a, 'type', 'veth', 'peer', 'name', inside,
               'netns', self.names[h])
            self.run('a', 'ip', 'link', 'set', outside, 'master', 'br0')
            self.run('a', 'ip', 'link', 'set', outside, 'up')
            self.run(h, 'ip', 'addr', 'add', self.address[h] + '/24', 'dev', inside)
            self.run(h, 'ip', 'link', 'set', inside, 'up')

    @staticmethod
    def remove_stale():
        """Namespaces left by a test process that no longer exists."""
        listing = subprocess.run(['ip', 'netns', 'list'], stdout=subprocess.PIPE,
                                 universal_newlines=True).stdout
        for name in re.findall(r'^(jrtest(\d+)_[abc])', listing, re.M):
            if not os.path.exists('/proc/%s' % name[1]):
                subprocess.run(['ip', 'netns', 'del', name[0]])

    def run(self, host, *args):
        sh('ip', 'netns', 'exec', self.names[host], *args)

    def start(self, host, command, log):
        """Starts `command` on `host` as that host's ROS user would: its own ROS_IP, the master
        on host a."""
        env = dict(os.environ, ROS_IP=self.address[host],
                   ROS_MASTER_URI='http://%s:11311' % self.address['a'])
        env.pop('ROS_HOSTNAME', None)
        proc = subprocess.Popen(['ip', 'netns', 'exec', self.names[host]] + command, env=env,
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        self.processes.append(proc)
        return proc

    def close(self):
        for proc in reversed(self.processes):
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGINT)
        for proc in reversed(self.processes):
            try:
                proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
        self.remove_namespaces()

    def remove_namespaces(self):
        for h in 'abc':
            subprocess.run(['ip', 'netns', 'del', self.names[h]], stderr=subprocess.DEVNULL)


def wait_for_master(hosts, deadline):
    while time.monotonic() < deadline:
        probe = subprocess.run(
            ['ip', 'netns', 'exec', hosts.names['a'], 'rostopic', 'list'],
            env=dict(os.environ, ROS_MASTER_URI='http://%s:11311' % hosts.address['a']),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if probe.returncode == 0:
            return
        time.sleep(0.2)  # the master has no event to wait on from outside its namespace
    raise AssertionError('no ROS master on host a')


class TestMultiHost(unittest.TestCase):
    def test_training_over_three_hosts(self):
        # rostest ends a test that overruns with SIGTERM: clean up then as well.
        signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(SystemExit(1)))
        run_dir = tempfile.mkdtemp(prefix='jetbot_rl_test_multi_host_')
        log = open(os.path.join(run_dir, 'hosts.log'), 'w')
        hosts = Hosts()
        try:
            deadline = time.monotonic() + TIMEOUT
            hosts.start('a', ['roscore', '-p', '11311'], log)
            wait_for_master(hosts, deadline)
            for k, h in enumerate('bc'):
                hosts.start(h, ['roslaunch', 'jetbot_rl', 'env_host.launch', 'num_env_nodes:=1',
                                'first:=%d' % k, 'num_envs:=50', 'num_threads:=1',
                                'output:=log'], log)
            trainer = hosts.start('a', [
                'roslaunch', 'jetbot_rl', 'train.launch', 'num_env_nodes:=0', 'env_nodes:=' + NODES,
                'iterations:=40', 'run_dir:=' + run_dir, 'end_launch:=false', 'required:=true'],
                log)
            trainer.wait(timeout=max(1.0, deadline - time.monotonic()))
        finally:
            hosts.close()
            log.close()
        with open(os.path.join(run_dir, 'hosts.log')) as f:
            output = f.read()
        summary_path = os.path.join(run_dir, 'summary.yaml')
        self.assertTrue(os.path.isfile(summary_path), output[-3000:])
        with open(summary_path) as f:
            summary = f.read()
        print(summary)
        self.assertIn('status: completed', summary)
        with open(os.path.join(run_dir, 'config.yaml')) as f:
            self.assertIn('env_num_envs: 100', f.read())
        reached = re.search(r'target_reached_at_env_steps: (\d+)', summary)
        self.assertIsNotNone(reached, 'the velocity target %.2f was never reached' % TARGET)
        print('FIGURE: over hosts b and c (50 envs each), the velocity target was reached after '
              '%s env steps' % reached.group(1))
        listing = subprocess.run(['ip', 'netns', 'list'], stdout=subprocess.PIPE,
                                 universal_newlines=True).stdout
        self.assertNotIn(hosts.prefix, listing, 'namespaces left behind')


if __name__ == '__main__':
    rospy.init_node('test_multi_host')
    rostest.rosrun('jetbot_rl', 'test_multi_host', TestMultiHost)
