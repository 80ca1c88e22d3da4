"""Helpers of the PPO rostests: progress.csv, the latched ~training_stats topic, node runs."""
import csv
import os
import subprocess
import threading
import time

import rospy
from std_msgs.msg import Float32MultiArray

REQUIRED_HEADER = ('iteration,env_steps,mean_reward_per_step,mean_episode_return,'
                   'env_steps_per_s,elapsed_s')
TIMING_COLUMNS = ('env_steps_per_s', 'elapsed_s', 'collection_s', 'update_s')
TIMEOUT = 120.0  # s: generous, for a loaded 2-core machine


def read_csv(path):
    """(header line, list of row dicts with float values)."""
    with open(path, newline='') as f:
        header = f.readline().strip()
        f.seek(0)
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return header, rows


def learning_columns(path):
    """Every CSV cell but the timing columns, as strings (exact comparison)."""
    with open(path, newline='') as f:
        rows = list(csv.reader(f))
    keep = [i for i, name in enumerate(rows[0]) if name not in TIMING_COLUMNS]
    return [[row[i] for i in keep] for row in rows]


class StatsWatcher(object):
    """Collects ~training_stats (latched Float32MultiArray) of one trainer."""

    def __init__(self, topic):
        self.cond = threading.Condition()
        self.messages = []
        self.sub = rospy.Subscriber(topic, Float32MultiArray, self._on_stats)

    def _on_stats(self, msg):
        with self.cond:
            self.messages.append(msg)
            self.cond.notify_all()

    def wait_iteration(self, iteration, timeout=TIMEOUT):
        """Blocks until a message reports `iteration` or later; returns it as a dict."""
        def reached():
            return self.messages and self.messages[-1].data[0] >= iteration
        with self.cond:
            if not self.cond.wait_for(lambda: reached() or rospy.is_shutdown(), timeout):
                raise AssertionError('no training_stats for iteration %d within %.0f s'
                                     % (iteration, timeout))
            msg = self.messages[-1]
        names = msg.layout.dim[0].label.split(',')
        return dict(zip(names, msg.data))


def wait_completed(run_dir, timeout=TIMEOUT):
    """Blocks until the run in `run_dir` has written its summary.yaml with `status: completed`
    (written after its last progress.csv row). For trainings launched before the test: their
    latched ~training_stats ends with the trainer, which may finish before a loaded test's
    subscriber connects. Polls the file: nothing announces it."""
    path = os.path.join(run_dir, 'summary.yaml')
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and not rospy.is_shutdown():
        try:
            with open(path) as f:
                if 'status: completed' in f.read():
                    return
        except FileNotFoundError:
            pass
        time.sleep(0.1)
    raise AssertionError('%s: no completed run within %.0f s' % (path, timeout))


_NODE_PATHS = {}


def node_path(node_type):
    """The jetbot_rl program rosrun would run, found once (rosrun looks for it at every start:
    about 0.5 s on a loaded machine)."""
    if node_type not in _NODE_PATHS:
        import roslib.packages
        paths = roslib.packages.find_node('jetbot_rl', node_type)
        assert paths, 'no jetbot_rl program named %s' % node_type
        _NODE_PATHS[node_type] = paths[0]
    return _NODE_PATHS[node_type]


def run_node(node_type, name, params, timeout=TIMEOUT):
    """Runs a jetbot_rl node to its end; returns (exit code, output)."""
    command = [node_path(node_type), '__name:=' + name]
    command += ['_%s:=%s' % (k, v) for k, v in params.items()]
    proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=timeout, universal_newlines=True)
    return proc.returncode, proc.stdout


def start_node(node_type, name, params):
    command = [node_path(node_type), '__name:=' + name]
    command += ['_%s:=%s' % (k, v) for k, v in params.items()]
    # the node itself (no rosrun), so signals reach it directly.
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True)

