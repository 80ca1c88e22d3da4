#!/usr/bin/python3
"""Turns a training run's progress.csv into a learning-curve PNG and prints the final figures.

    rosrun jetbot_rl plot_learning_curve.py RUN_DIR_OR_CSV [-o OUT.png] [--target 0.54]

Writes RUN_DIR/learning_curve.png by default (the CSV's directory). Uses matplotlib's Agg
backend, so no display is needed.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

REQUIRED = ['iteration', 'env_steps', 'mean_reward_per_step', 'mean_episode_return',
            'env_steps_per_s', 'elapsed_s']


def read_progress(path):
    with open(path, newline='') as f:
        reader = csv.DictReader(f)
        missing = [c for c in REQUIRED if c not in (reader.fieldnames or [])]
        if missing:
            raise ValueError('%s lacks the column(s) %s' % (path, ', '.join(missing)))
        rows = [{k: float(v) for k, v in row.items() if k is not None and v not in (None, '')}
                for row in reader]
    if not rows:
        raise ValueError('%s has no rows yet' % path)
    return rows


def figures(rows, target):
    """The final figures, as (name, value) pairs."""
    reward = [r['mean_reward_per_step'] for r in rows]
    last = rows[-1]
    reached = next((r for r in rows if r['mean_reward_per_step'] >= target), None)
    tail = reward[-10:]
    out = [
        ('iterations', '%d' % last['iteration']),
        ('env_steps', '%d' % last['env_steps']),
        ('elapsed_s', '%.1f' % last['elapsed_s']),
        ('first_mean_reward_per_step', '%.4f' % reward[0]),
        ('final_mean_reward_per_step', '%.4f' % reward[-1]),
        ('mean_reward_per_step_last_10_iterations', '%.4f' % (sum(tail) / len(tail))),
        ('best_mean_reward_per_step', '%.4f' % max(reward)),
        ('final_mean_episode_return', '%.2f' % last['mean_episode_return']
         if not math.isnan(last['mean_episode_return']) else 'nan'),
        ('mean_env_steps_per_s', '%.0f' % (last['env_steps'] / last['elapsed_s']
                                           if last['elapsed_s'] > 0 else float('nan'))),
        ('target_mean_reward_per_step', '%.4f' % target),
    ]
    if reached:
        out += [('target_reached_at_iteration', '%d' % reached['iteration']),
                ('target_reached_at_env_steps', '%d' % reached['env_steps']),
                ('target_reached_at_elapsed_s', '%.1f' % reached['elapsed_s'])]
    else:
        out += [('target_reached_at_iteration', 'never')]
    return out


def plot(rows, target, out, title):
    steps = [r['env_steps'] for r in rows]
    reward = [r['mean_reward_per_step'] for r in rows]
    episode = [r['mean_episode_return'] for r in rows]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax1.plot(steps, reward, color='tab:blue', label='mean reward per step')
    ax1.axhline(target, color='tab:red', linestyle='--', linewidth=1,
                label='target %.3f m/s' % target)
    ax1.set_ylabel('mean reward per step [m/s]')
    ax1.grid(True, alpha=0.3)
    ax1.legend(loc='lower right')
    ax1.set_title(title)
    ax2.plot(steps, episode, color='tab:green', label='mean episode return (last 100)')
    ax2.set_ylabel('episode return')
    ax2.set_xlabel('env steps')
    ax2.grid(True, alpha=0.3)
    ax2.legend(loc='lower right')
    # Wall time on a secondary axis, read from the same rows.
    top = ax1.secondary_xaxis(
        'top', functions=(lambda x: _interp(x, steps, [r['elapsed_s'] for r in rows]),
                          lambda t: _interp(t, [r['elapsed_s'] for r in rows], steps)))
    top.set_xlabel('wall time [s]')
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def _interp(x, xs, ys):
    """Piecewise-linear map for the secondary axis (scalars or arrays), extended linearly
    beyond the data with the overall slope (matplotlib asks for the whole axis range)."""
    import numpy as np
    xs = np.concatenate(([0.0], np.asarray(xs, dtype=float)))
    ys = np.concatenate(([0.0], np.asarray(ys, dtype=float)))
    slope = (ys[-1] - ys[0]) / (xs[-1] - xs[0]) if xs[-1] > xs[0] else 1.0
    x = np.asarray(x, dtype=float)
    inside = np.interp(x, xs, ys)
    return np.where(x > xs[-1], ys[-1] + (x - xs[-1]) * slope,
                    np.where(x < xs[0], ys[0] + (x - xs[0]) * slope, inside))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('run', help='run directory or its progress.csv')
    parser.add_argument('-o', '--output', help='PNG to write (default: RUN_DIR/learning_curve.png)')
    parser.add_argument('--target', type=float, default=0.54,
                        help='target mean reward per step [m/s] (default 0.54 = 90%% of 0.6)')
    parser.add_argument('--title', default=None, help='plot title')
    args = parser.parse_args(argv)

    csv_path = os.path.join(args.run, 'progress.csv') if os.path.isdir(args.run) else args.run
    try:
        rows = read_progress(csv_path)
    except (OSError, ValueError) as e:
        print('plot_learning_curve: %s' % e, file=sys.stderr)
        return 1
    out = args.output or os.path.join(os.path.dirname(os.path.abspath(csv_path)),
                                      'learning_curve.png')
    title = args.title or 'PPO on jetbot_env: %s' % os.path.dirname(os.path.abspath(csv_path))
    plot(rows, args.target, out, title)
    print('learning curve: %s' % out)
    for name, value in figures(rows, args.target):
        print('%s: %s' % (name, value))
    return 0


if __name__ == '__main__':
    sys.exit(main())
