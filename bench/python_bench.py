#!/usr/bin/python3
"""Lockstep round trips through JetbotVecEnv (the Python client) against a running jetbot_env.

    roslaunch jetbot_rl jetbot_env.launch num_envs:=1024 publish_clock:=false tf_envs:=0
    rosrun jetbot_rl python_bench.py --num-envs 1024 --steps 400

Each round trip is one JetbotVecEnv.step() (input checks, publish, wait for the answer, the
returned numpy arrays), timed from call to return after a warm-up of max(10, steps / 10) steps;
the actions cycle through 8 random sets within the action bounds (as jetbot_rl_ros_bench).
Prints the percentiles and, last, `env_steps_per_s=<number>` (env steps = steps x envs).
"""
import argparse
import sys
import time

import numpy as np

from jetbot_rl import JetbotVecEnv

ACTION_SETS = 8


class Renamed(argparse.Action):
    """An option that was renamed: refused (exit 2) with an error naming the new one."""

    def __init__(self, option_strings, dest, new, **kwargs):
        self.new = new
        super(Renamed, self).__init__(option_strings, dest, nargs='*', help=argparse.SUPPRESS,
                                      **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        parser.error('%s was renamed %s' % (option_string, self.new))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--num-envs', type=int, required=True,
                        help='envs in the batch (the num_envs of the nodes together)')
    parser.add_argument('--steps', type=int, required=True, help='timed round trips')
    parser.add_argument('--env-nodes', nargs='+', default=['/jetbot_env'], metavar='NAME',
                        help='env node(s), stepped as one batch (default /jetbot_env)')
    parser.add_argument('--timeout', type=float, default=30.0,
                        help='[s] for the node to appear and to answer (default 30)')
    parser.add_argument('--observation', default='vector', choices=['vector', 'image', 'dict'],
                        help="JetbotVecEnv's observation (default vector; image, dict: with a "
                        "camera)")
    parser.add_argument('--envs', action=Renamed, new='--num-envs')
    parser.add_argument('--node', action=Renamed, new='--env-nodes')
    args = parser.parse_args()
    if args.num_envs < 1 or args.steps < 1:
        parser.error('--num-envs and --steps must be >= 1')

    env = JetbotVecEnv(env_nodes=args.env_nodes, timeout=args.timeout,
                       observation=args.observation)
    if env.num_envs != args.num_envs:
        sys.exit('python_bench.py: %s: %d envs, not --num-envs %d: launch with num_envs:=%d'
                 % (' '.join(args.env_nodes), env.num_envs, args.num_envs, args.num_envs))
    rng = np.random.default_rng(12345)
    actions = [rng.uniform(env.action_low, env.action_high,
                           size=(env.num_envs, env.action_dim)).astype(np.float32)
               for _ in range(ACTION_SETS)]
    env.reset()
    warmup = max(10, args.steps // 10)
    for i in range(warmup):
        env.step(actions[i % ACTION_SETS])
    round_trips = np.empty(args.steps)
    clock = time.perf_counter
    start = clock()
    for i in range(args.steps):
        sent = clock()
        env.step(actions[i % ACTION_SETS])
        round_trips[i] = clock() - sent
    seconds = clock() - start
    env.close()

    us = round_trips * 1e6
    print('python_bench.py: %d envs, %d lockstep round trips through JetbotVecEnv.step()'
          % (args.num_envs, args.steps))
    print('python round_trip_us p50=%.1f p90=%.1f p99=%.1f max=%.1f  control_steps_per_s=%.0f'
          % (np.percentile(us, 50), np.percentile(us, 90), np.percentile(us, 99), us.max(),
             args.steps / seconds))
    print('env_steps_per_s=%.0f' % (args.steps * args.num_envs / seconds))


if __name__ == '__main__':
    main()
