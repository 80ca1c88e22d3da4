#!/usr/bin/python3
"""Soak test of a running jetbot_env node in lockstep mode: `--steps` lockstep steps through
~step, each followed by a ~reset of `--resets-per-step` envs (in turn), checking that the step
ids stay consecutive (in the answers and on ~env_step) and that the node's resident set stays
flat after `--warmup` steps. The node must run on this machine (its resident set is read from
/proc). Prints figures (lines starting with FIGURE:); exits 1 when a check fails.

    roslaunch jetbot_rl jetbot_env.launch num_envs:=100 publish_clock:=false tf_envs:=0
    rosrun jetbot_rl soak.py --steps 10000      # 10^6 env steps, 10^4 resets
"""
import argparse
import random
import sys
import threading
import time

import rospy

from jetbot_rl.msg import EnvSpec, EnvStep, WheelTargets
from jetbot_rl.process_info import node_pid, rss_kb
from jetbot_rl.srv import Reset, Step


def figure(text):
    sys.stdout.write('FIGURE: soak: %s\n' % text)
    sys.stdout.flush()


class PublishedSteps(object):
    """Checks every EnvStep on ~env_step as it arrives: each id is the previous one (a reset's
    state) or one more (a step)."""

    def __init__(self, topic):
        self.cond = threading.Condition()
        self.count = 0
        self.last = None
        self.errors = []
        self.sub = rospy.Subscriber(topic, EnvStep, self._on_step, tcp_nodelay=True)

    def _on_step(self, msg):
        with self.cond:
            if self.last is not None and msg.step - self.last not in (0, 1):
                self.errors.append('EnvStep %d after %d' % (msg.step, self.last))
            self.last = msg.step
            self.count += 1
            self.cond.notify_all()

    def wait(self, predicate, timeout):
        with self.cond:
            return self.cond.wait_for(lambda: predicate(self) or rospy.is_shutdown(), timeout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--env', default='/jetbot_env', help='the env node (default /jetbot_env)')
    parser.add_argument('--steps', type=int, default=10000, help='lockstep steps (10000)')
    parser.add_argument('--resets-per-step', type=int, default=1,
                        help='envs reset (one ~reset call) after every step (1)')
    parser.add_argument('--warmup', type=int, default=1000,
                        help='steps before the resident set is taken as the baseline (1000)')
    parser.add_argument('--max-rss-growth-kb', type=int, default=2048,
                        help='largest resident set growth after the warm-up [kB] (2048)')
    parser.add_argument('--timeout', type=float, default=30.0, help='per call [s] (30)')
    args = parser.parse_args(rospy.myargv()[1:])
    if args.warmup >= args.steps:
        parser.error('--warmup %d must be below --steps %d' % (args.warmup, args.steps))

    rospy.init_node('jetbot_rl_soak', anonymous=True)
    spec = rospy.wait_for_message(args.env + '/spec', EnvSpec, args.timeout)
    rospy.wait_for_service(args.env + '/step', args.timeout)
    rospy.wait_for_service(args.env + '/reset', args.timeout)
    step_srv = rospy.ServiceProxy(args.env + '/step', Step, persistent=True)
    reset_srv = rospy.ServiceProxy(args.env + '/reset', Reset, persistent=True)
    pid = node_pid(args.env)
    published = PublishedSteps(args.env + '/env_step')

    # Reset until its publication arrives: our subscription is connected from then on.
    state = None
    deadline = time.monotonic() + args.timeout
    while state is None or not published.wait(lambda p: p.count > 0, 1.0):
        if time.monotonic() > deadline:
            sys.exit('no EnvStep on %s/env_step after a reset' % args.env)
        state = reset_srv(env_ids=[], seed=0, episode_steps=[]).state
    with published.cond:
        published.count, published.errors = 0, []
        published.last = state.step

    rng = random.Random(0)
    actions = [[rng.uniform(-20.0, 20.0) for _ in range(spec.num_envs * spec.action_dim)]
               for _ in range(16)]  # [rad/s], one of them per step
    first_step = state.step
    answers_out_of_order = 0
    resets = 0
    rss = []  # (steps done, kB) from the end of the warm-up on
    sample_every = max(1, (args.steps - args.warmup) // 20)
    started = time.monotonic()
    for k in range(args.steps):
        targets = WheelTargets(step=state.step, velocities=actions[k % len(actions)])
        res = step_srv(targets)
        if not res.success or res.state.step != state.step + 1:
            answers_out_of_order += 1
            print('step %d: %s, answered step %d' % (state.step, res.message or 'ok',
                                                     res.state.step))
        state = res.state
        ids = [(k * args.resets_per_step + j) % spec.num_envs
               for j in range(args.resets_per_step)]
        res = reset_srv(env_ids=ids, seed=-1, episode_steps=[])
        if not res.success or res.state.step != state.step:
            answers_out_of_order += 1
            print('reset after step %d: %s, answered step %d' % (state.step, res.message,
                                                                 res.state.step))
        resets += len(ids)
        done = k + 1
        if done >= args.warmup and (done - args.warmup) % sample_every == 0:
            rss.append((done, rss_kb(pid)))
    seconds = time.monotonic() - started
    rss.append((args.steps, rss_kb(pid)))
    expected = 2 * args.steps  # one EnvStep per step and one per reset
    if not published.wait(lambda p: p.count >= expected, args.timeout):
        published.errors.append('%d EnvSteps published, %d expected' % (published.count,
                                                                          expected))
    with published.cond:
        errors = list(published.errors)
        count = published.count

    env_steps = args.steps * spec.num_envs
    figure('%d envs x %d lockstep steps = %d env steps, %d env resets in %d ~reset calls, '
           '%.1f s (%.0f env steps/s with the resets)'
           % (spec.num_envs, args.steps, env_steps, resets, args.steps, seconds,
              env_steps / seconds))
    figure('step ids %d..%d: %d ~step and ~reset answers out of order, %d EnvSteps published, '
           '%d out of order' % (first_step, state.step, answers_out_of_order, count, len(errors)))
    base = rss[0][1]
    growth = rss[-1][1] - base
    figure('node resident set %.1f MB after %d warm-up steps, %.1f MB at the end (%+d kB), '
           'largest %+d kB, smallest %+d kB over %d samples'
           % (base / 1024.0, args.warmup, rss[-1][1] / 1024.0, growth,
              max(kb for _, kb in rss) - base, min(kb for _, kb in rss) - base, len(rss)))
    failed = []
    if answers_out_of_order:
        failed.append('%d answers out of order' % answers_out_of_order)
    if state.step != first_step + args.steps:
        failed.append('ended at step %d, expected %d' % (state.step, first_step + args.steps))
    if errors:
        failed.append('~env_step: ' + '; '.join(errors[:5]))
    if max(kb for _, kb in rss) - base > args.max_rss_growth_kb:
        failed.append('resident set grew by %d kB after the warm-up (limit %d kB)'
                      % (max(kb for _, kb in rss) - base, args.max_rss_growth_kb))
    if failed:
        print('FAILED: ' + '; '.join(failed))
        return 1
    print('passed')
    return 0


if __name__ == '__main__':
    sys.exit(main())
